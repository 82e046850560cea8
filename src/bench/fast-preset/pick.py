"""Summarises src/bench/fast-preset/run.sh: per mesh and candidate, build time, expected cost against the exact tree,
R rays per second and the total time for 1, 10 and 100 rays per triangle (best in bold), then the candidates ranked by the
geometric mean of total time over the best, among those within 1.30 x the exact tree's expected cost on every mesh.
Usage: pick.py OUTDIR"""
import csv, glob, os, sys, collections, math
if len(sys.argv) != 2 or not glob.glob(os.path.join(sys.argv[1], '*--exact-l1.csv')):
    sys.exit('usage: pick.py OUTDIR (the folder run.sh wrote, with its exact-l1 candidate)')
rows = collections.defaultdict(dict)
for f in glob.glob(os.path.join(sys.argv[1], '*.csv')):
    mesh, cand = os.path.basename(f)[:-4].split('--')
    r = next(csv.DictReader(open(f)))
    rows[mesh][cand] = r
cands = sorted({c for m in rows.values() for c in m})
print('| mesh | candidate | build ms | expected cost (x exact) | nodes | R Mrays/s | 1 r/tri ms | 10 | 100 |')
print('| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |')
ratio = collections.defaultdict(list)
for mesh in sorted(rows):
    base = float(rows[mesh]['exact-l1']['expected_cost'])
    best = {k: min(float(r[k]) for c, r in rows[mesh].items() if float(r['expected_cost']) <= 1.30 * base) for k in ('total_ms_1rpt','total_ms_10rpt','total_ms_100rpt')}
    for c in cands:
        r = rows[mesh].get(c)
        if not r: continue
        cost = float(r['expected_cost']) / base
        cells = []
        for k in ('total_ms_1rpt','total_ms_10rpt','total_ms_100rpt'):
            v = float(r[k]); mark = '**' if v == best[k] else ''
            cells.append(f'{mark}{v:.0f}{mark}')
            if cost <= 1.30: ratio[c].append(v / best[k])
            else: ratio[c].append(float('inf'))
        print(f"| {mesh} | {c} | {float(r['build_ms']):.1f} | {float(r['expected_cost']):.1f} ({cost:.3f}) | {r['nodes']} | {float(r['mrays_per_s']):.3f} | " + ' | '.join(cells) + ' |')
print()
print('geometric mean of total time / best, over meshes x {1,10,100} rays per triangle (cost <= 1.30 x exact):')
for c in sorted(ratio, key=lambda c: sum(math.log(x) for x in ratio[c]) / len(ratio[c])):
    g = math.exp(sum(math.log(x) for x in ratio[c]) / len(ratio[c]))
    print(f'  {c:10s} {g:.3f}  worst {max(ratio[c]):.3f}')
