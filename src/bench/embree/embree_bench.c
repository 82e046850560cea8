/*
 * Embree anchor for the ray-casting benchmark (docs/benchmark-spec.md).
 *
 * Usage: embree_bench MESH.obj [more.obj ...]
 *
 * Main figures (the spec line, "system" = embree3-high-1t):
 *   device config "threads=1", scene build quality RTC_BUILD_QUALITY_HIGH,
 *   build = rtcNewScene .. rtcCommitScene over shared (user-owned) buffers,
 *   median of 5 builds after 2 warm-ups; tracing with rtcIntersect1 in one
 *   thread, median of 5 runs after 2 warm-ups, rays pre-generated in arrays.
 * Secondary figures (lines starting with '#'): P traced as packets of 16 (4 x 4 tiles),
 *   MEDIUM quality build (and its
 *   trace speed), builds with the default device thread count, BVH statistics
 *   scraped from Embree's own verbose=2 report (Embree has no public API for them).
 *
 * Ray generation is done in double precision, exactly per the spec, then
 * converted to float for Embree.  Compile with -ffp-contract=off so that the
 * double arithmetic is not fused into FMAs (Java never fuses).
 */
#define _GNU_SOURCE
#include <embree3/rtcore.h>
#include <xmmintrin.h>
#include <pmmintrin.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <fcntl.h>

#define WARMUPS 2
#define RUNS 5
#define IMG 1024
#define NRAND 1000000

/* ------------------------------------------------------------------ mesh */
typedef struct {
    float *vf;          /* 3 floats per vertex, +1 float padding for Embree's 16-byte loads */
    double *vd;         /* same vertices in double (bbox is taken from these) */
    size_t nv, capv;
    unsigned *idx;      /* 3 per triangle */
    size_t nt, capt;
} Mesh;

static void push_vertex(Mesh *m, const char *p) {
    if (m->nv == m->capv) {
        m->capv = m->capv ? 2 * m->capv : 1024;
        m->vf = realloc(m->vf, (3 * m->capv + 4) * sizeof(float));
        m->vd = realloc(m->vd, 3 * m->capv * sizeof(double));
    }
    char *end;
    for (int k = 0; k < 3; k++) {
        while (*p == ' ' || *p == '\t') p++;
        double d = strtod(p, &end);
        float f = strtof(p, NULL);   /* correctly rounded, like Float.parseFloat */
        p = end;
        m->vd[3 * m->nv + k] = d;
        m->vf[3 * m->nv + k] = f;
    }
    m->nv++;
}

static void push_tri(Mesh *m, unsigned a, unsigned b, unsigned c) {
    if (m->nt == m->capt) {
        m->capt = m->capt ? 2 * m->capt : 1024;
        m->idx = realloc(m->idx, 3 * m->capt * sizeof(unsigned));
    }
    m->idx[3 * m->nt] = a; m->idx[3 * m->nt + 1] = b; m->idx[3 * m->nt + 2] = c;
    m->nt++;
}

static int load_obj(const char *path, Mesh *m) {
    FILE *f = fopen(path, "r");
    if (!f) { perror(path); return 0; }
    memset(m, 0, sizeof *m);
    char *line = NULL; size_t cap = 0;
    long *poly = NULL; size_t pcap = 0;
    while (getline(&line, &cap, f) > 0) {
        char *p = line;
        while (*p == ' ' || *p == '\t') p++;
        if (p[0] == 'v' && (p[1] == ' ' || p[1] == '\t')) {
            push_vertex(m, p + 2);
        } else if (p[0] == 'f' && (p[1] == ' ' || p[1] == '\t')) {
            size_t n = 0;
            p += 2;
            for (;;) {
                while (*p == ' ' || *p == '\t') p++;
                if (!*p || *p == '\n' || *p == '\r') break;
                char *end;
                long v = strtol(p, &end, 10);
                if (end == p) break;
                p = end;
                while (*p && *p != ' ' && *p != '\t' && *p != '\n' && *p != '\r') p++; /* skip /vt/vn */
                long i0 = v > 0 ? v - 1 : (long)m->nv + v;   /* 1-based or negative-relative */
                if (n == pcap) { pcap = pcap ? 2 * pcap : 16; poly = realloc(poly, pcap * sizeof(long)); }
                poly[n++] = i0;
            }
            for (size_t k = 1; k + 1 < n; k++)
                push_tri(m, (unsigned)poly[0], (unsigned)poly[k], (unsigned)poly[k + 1]);
        }
    }
    free(line); free(poly); fclose(f);
    return 1;
}

/* ------------------------------------------------------------------ timing */
static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
static int cmpd(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}
static double median(double *v, int n) { qsort(v, n, sizeof *v, cmpd); return v[n / 2]; }

/* ------------------------------------------------------------------ embree */
static void on_error(void *user, enum RTCError code, const char *str) {
    (void)user;
    fprintf(stderr, "embree error %d: %s\n", (int)code, str ? str : "");
    exit(2);
}

static RTCScene build_scene(RTCDevice dev, const Mesh *m, enum RTCBuildQuality q) {
    RTCScene sc = rtcNewScene(dev);
    rtcSetSceneBuildQuality(sc, q);
    RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(g, q);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, m->vf, 0, 12, m->nv);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m->idx, 0, 12, m->nt);
    rtcCommitGeometry(g);
    rtcAttachGeometry(sc, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(sc);
    return sc;
}

/* median build ms over RUNS after WARMUPS; returns the last scene (kept) */
static double time_build(RTCDevice dev, const Mesh *m, enum RTCBuildQuality q, RTCScene *keep) {
    double t[RUNS];
    RTCScene sc = NULL;
    for (int r = 0; r < WARMUPS + RUNS; r++) {
        if (sc) rtcReleaseScene(sc);
        double t0 = now();
        sc = build_scene(dev, m, q);
        double t1 = now();
        if (r >= WARMUPS) t[r - WARMUPS] = t1 - t0;
    }
    if (keep) *keep = sc; else rtcReleaseScene(sc);
    return 1e3 * median(t, RUNS);
}

typedef struct { float *o, *d; size_t n; } Rays;   /* 3 floats each */

typedef struct { long hits; double tsum; double mrays; } TraceResult;

static TraceResult trace(RTCScene sc, const Rays *R) {
    double t[RUNS];
    TraceResult res = {0, 0, 0};
    for (int r = 0; r < WARMUPS + RUNS; r++) {
        struct RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        long hits = 0; double tsum = 0.0;
        double t0 = now();
        for (size_t i = 0; i < R->n; i++) {
            struct RTCRayHit rh __attribute__((aligned(16)));
            rh.ray.org_x = R->o[3 * i]; rh.ray.org_y = R->o[3 * i + 1]; rh.ray.org_z = R->o[3 * i + 2];
            rh.ray.dir_x = R->d[3 * i]; rh.ray.dir_y = R->d[3 * i + 1]; rh.ray.dir_z = R->d[3 * i + 2];
            rh.ray.tnear = 0.0f; rh.ray.tfar = INFINITY;
            rh.ray.time = 0.0f; rh.ray.mask = 0xFFFFFFFFu; rh.ray.id = 0; rh.ray.flags = 0;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID; rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(sc, &ctx, &rh);
            if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) { hits++; tsum += (double)rh.ray.tfar; }
        }
        double t1 = now();
        if (r > 0 && (hits != res.hits || tsum != res.tsum)) fprintf(stderr, "WARNING: checksum changed between runs\n");
        res.hits = hits; res.tsum = tsum;
        if (r >= WARMUPS) t[r - WARMUPS] = t1 - t0;
    }
    res.mrays = (double)R->n / median(t, RUNS) / 1e6;
    return res;
}


/* P traced as packets of 16 rays, 4 x 4 pixel tiles (rtcIntersect16): Embree's answer for
 * coherent rays, beside the single-ray figure of the spec line; same hits, same distance sum. */
static TraceResult trace_tiles16(RTCScene sc, const Rays *R) {
    double t[RUNS];
    TraceResult res = {0, 0, 0};
    for (int r = 0; r < WARMUPS + RUNS; r++) {
        struct RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        long hits = 0; double tsum = 0.0;
        int valid[16]; for (int l = 0; l < 16; l++) valid[l] = -1;
        struct RTCRayHit16 rh __attribute__((aligned(64)));
        double t0 = now();
        for (int ty = 0; ty < IMG; ty += 4)
            for (int tx = 0; tx < IMG; tx += 4) {
                for (int l = 0; l < 16; l++) {
                    size_t i = (size_t)(ty + l / 4) * IMG + (tx + l % 4);
                    rh.ray.org_x[l] = R->o[3 * i]; rh.ray.org_y[l] = R->o[3 * i + 1]; rh.ray.org_z[l] = R->o[3 * i + 2];
                    rh.ray.dir_x[l] = R->d[3 * i]; rh.ray.dir_y[l] = R->d[3 * i + 1]; rh.ray.dir_z[l] = R->d[3 * i + 2];
                    rh.ray.tnear[l] = 0.0f; rh.ray.tfar[l] = INFINITY;
                    rh.ray.time[l] = 0.0f; rh.ray.mask[l] = 0xFFFFFFFFu; rh.ray.id[l] = 0; rh.ray.flags[l] = 0;
                    rh.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID; rh.hit.instID[0][l] = RTC_INVALID_GEOMETRY_ID;
                }
                rtcIntersect16(valid, sc, &ctx, &rh);
                for (int l = 0; l < 16; l++)
                    if (rh.hit.geomID[l] != RTC_INVALID_GEOMETRY_ID) { hits++; tsum += (double)rh.ray.tfar[l]; }
            }
        double t1 = now();
        res.hits = hits; res.tsum = tsum;
        if (r >= WARMUPS) t[r - WARMUPS] = t1 - t0;
    }
    res.mrays = (double)R->n / median(t, RUNS) / 1e6;
    return res;
}

/* ------------------------------------------------------------------ ray sets (double, per spec) */
static void normalize3(double v[3]) {
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l; v[1] /= l; v[2] /= l;
}

static void make_P(const double mn[3], const double mx[3], Rays *R) {
    double c[3], e[3], d2 = 0;
    for (int k = 0; k < 3; k++) { c[k] = (mn[k] + mx[k]) / 2; double t = mx[k] - mn[k]; d2 += t * t; }
    double d = sqrt(d2);
    double dirv[3] = {1.0, 0.5, 2.0};
    normalize3(dirv);
    for (int k = 0; k < 3; k++) e[k] = c[k] + 1.5 * d * dirv[k];
    double fw[3] = {c[0] - e[0], c[1] - e[1], c[2] - e[2]};
    normalize3(fw);
    const double up[3] = {0.0, 1.0, 0.0};
    double rt[3] = {fw[1] * up[2] - fw[2] * up[1], fw[2] * up[0] - fw[0] * up[2], fw[0] * up[1] - fw[1] * up[0]};
    normalize3(rt);
    double u2[3] = {rt[1] * fw[2] - rt[2] * fw[1], rt[2] * fw[0] - rt[0] * fw[2], rt[0] * fw[1] - rt[1] * fw[0]};
    double s = tan(20.0 * M_PI / 180.0);
    R->n = (size_t)IMG * IMG;
    R->o = malloc(3 * R->n * sizeof(float));
    R->d = malloc(3 * R->n * sizeof(float));
    size_t n = 0;
    for (int j = 0; j < IMG; j++) {          /* rows from the top */
        for (int i = 0; i < IMG; i++) {      /* columns from the left */
            double x = (2 * (i + 0.5) / IMG - 1) * s;
            double y = (1 - 2 * (j + 0.5) / IMG) * s;
            double dv[3];
            for (int k = 0; k < 3; k++) dv[k] = fw[k] + x * rt[k] + y * u2[k];
            normalize3(dv);
            for (int k = 0; k < 3; k++) { R->o[3 * n + k] = (float)e[k]; R->d[3 * n + k] = (float)dv[k]; }
            n++;
        }
    }
}

static uint64_t sm_state;
static double next_u(void) {
    sm_state += 0x9E3779B97F4A7C15ULL;
    uint64_t z = sm_state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z = z ^ (z >> 31);
    return (double)(z >> 11) * 0x1.0p-53;
}

static void make_R(const double mn[3], const double mx[3], Rays *R) {
    sm_state = 42;
    R->n = NRAND;
    R->o = malloc(3 * R->n * sizeof(float));
    R->d = malloc(3 * R->n * sizeof(float));
    for (size_t n = 0; n < R->n; n++) {
        double ux = next_u(), uy = next_u(), uz = next_u(), u = next_u(), v = next_u();
        double o[3] = {mn[0] + ux * (mx[0] - mn[0]), mn[1] + uy * (mx[1] - mn[1]), mn[2] + uz * (mx[2] - mn[2])};
        double zc = 1 - 2 * u;
        double phi = 2 * M_PI * v;
        double r = sqrt(fmax(0.0, 1 - zc * zc));
        double dv[3] = {r * cos(phi), r * sin(phi), zc};
        for (int k = 0; k < 3; k++) { R->o[3 * n + k] = (float)o[k]; R->d[3 * n + k] = (float)dv[k]; }
    }
}

/* ------------------------------------------------------------------ BVH stats from verbose=2 */
typedef struct { long inner, leaves, depth; double avg_refs; char builder[160]; char isect[160]; } Stats;

static void bvh_stats(const Mesh *m, Stats *st) {
    memset(st, 0, sizeof *st);
    char tmpl[] = "/tmp/embree_statsXXXXXX";
    int fd = mkstemp(tmpl);
    fflush(stdout);
    int saved = dup(1);
    dup2(fd, 1);
    RTCDevice dev = rtcNewDevice("threads=1,verbose=2");
    rtcSetDeviceErrorFunction(dev, on_error, NULL);
    RTCScene sc = build_scene(dev, m, RTC_BUILD_QUALITY_HIGH);
    struct RTCIntersectContext ctx; rtcInitIntersectContext(&ctx);
    struct RTCRayHit rh __attribute__((aligned(16)));
    memset(&rh, 0, sizeof rh); rh.ray.dir_z = 1; rh.ray.tfar = INFINITY; rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(sc, &ctx, &rh);
    rtcReleaseScene(sc);
    rtcReleaseDevice(dev);
    fflush(stdout);
    dup2(saved, 1); close(saved); close(fd);
    FILE *f = fopen(tmpl, "r");
    char line[4096];
    long prims = 0; double leaf_bpp = 0, leaf_fill = 0;
    while (f && fgets(line, sizeof line, f)) {
        char *p;
        if ((p = strstr(line, "building BVH"))) { line[strcspn(line, "\n")] = 0; snprintf(st->builder, sizeof st->builder, "%s", p + 9); }
        if ((p = strstr(line, "intersector1  ="))) { line[strcspn(line, "\n")] = 0; if (!st->isect[0]) snprintf(st->isect, sizeof st->isect, "%s", p + 16); }
        if ((p = strstr(line, "primitives ="))) sscanf(p, "primitives = %ld, vertices = %*d, depth = %ld", &prims, &st->depth);
        if ((p = strstr(line, "getAABBNodes "))) { char *q = strstr(p, "#nodes ="); if (q) sscanf(q, "#nodes = %ld", &st->inner); }
        if ((p = strstr(line, "  leaves "))) {
            char *q = strstr(p, "#nodes =");
            if (q) sscanf(q, "#nodes = %ld ( %lf%% filled), #bytes/prim = %lf", &st->leaves, &leaf_fill, &leaf_bpp);
        }
    }
    if (f) fclose(f);
    unlink(tmpl);
    /* Triangle4 leaf block = 176 bytes (v0,e1,e2: 3x48, geomIDs 16, primIDs 16) holding up to 4 refs */
    if (st->leaves > 0 && prims > 0) {
        double blocks = leaf_bpp * (double)prims / 176.0;
        st->avg_refs = blocks * 4.0 * leaf_fill / 100.0 / (double)st->leaves;
    }
}

/* ------------------------------------------------------------------ main */
int main(int argc, char **argv) {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);        /* as Embree's docs ask */
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    int bbox_from_float = getenv("BBOX_FROM_FLOAT") != NULL;
    printf("# embree %s; columns: system mesh tris build_ms nodes leaves depth P_hits P_tsum P_mrays R_hits R_tsum R_mrays\n",
           RTC_VERSION_STRING);
    for (int a = 1; a < argc; a++) {
        Mesh m;
        if (!load_obj(argv[a], &m)) continue;
        const char *base = strrchr(argv[a], '/'); base = base ? base + 1 : argv[a];
        char name[256]; snprintf(name, sizeof name, "%s", base);
        char *dot = strrchr(name, '.'); if (dot) *dot = 0;

        double mn[3] = {INFINITY, INFINITY, INFINITY}, mx[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t i = 0; i < m.nv; i++)
            for (int k = 0; k < 3; k++) {
                double v = bbox_from_float ? (double)m.vf[3 * i + k] : m.vd[3 * i + k];
                if (v < mn[k]) mn[k] = v;
                if (v > mx[k]) mx[k] = v;
            }

        Rays P, R;
        make_P(mn, mx, &P);
        make_R(mn, mx, &R);

        Stats st;
        bvh_stats(&m, &st);

        /* main: threads=1, HIGH */
        RTCDevice dev1 = rtcNewDevice("threads=1");
        rtcSetDeviceErrorFunction(dev1, on_error, NULL);
        RTCScene scH;
        double bH = time_build(dev1, &m, RTC_BUILD_QUALITY_HIGH, &scH);
        TraceResult pH = trace(scH, &P), rH = trace(scH, &R), pH16 = trace_tiles16(scH, &P);
        rtcReleaseScene(scH);
        printf("embree3-high-1t %s %zu %.1f %ld %ld %ld %ld %.6f %.2f %ld %.6f %.2f\n",
               name, m.nt, bH, st.inner + st.leaves, st.leaves, st.depth,
               pH.hits, pH.tsum, pH.mrays, rH.hits, rH.tsum, rH.mrays);
        fflush(stdout);

        /* secondary: MEDIUM, threads=1 */
        RTCScene scM;
        double bM = time_build(dev1, &m, RTC_BUILD_QUALITY_MEDIUM, &scM);
        TraceResult pM = trace(scM, &P), rM = trace(scM, &R);
        rtcReleaseScene(scM);
        rtcReleaseDevice(dev1);

        /* secondary: default thread count */
        RTCDevice devN = rtcNewDevice(NULL);
        rtcSetDeviceErrorFunction(devN, on_error, NULL);
        double bHN = time_build(devN, &m, RTC_BUILD_QUALITY_HIGH, NULL);
        double bMN = time_build(devN, &m, RTC_BUILD_QUALITY_MEDIUM, NULL);
        rtcReleaseDevice(devN);

        printf("#  %s: bvh = %s | %s | inner=%ld leaves=%ld depth=%ld avg_tri_refs_per_leaf~%.2f\n",
               name, st.builder, st.isect, st.inner, st.leaves, st.depth, st.avg_refs);
        printf("#  %s: MEDIUM 1t build_ms=%.1f P %ld %.6f %.2f Mrays/s, R %ld %.6f %.2f Mrays/s\n",
               name, bM, pM.hits, pM.tsum, pM.mrays, rM.hits, rM.tsum, rM.mrays);
        printf("#  %s: HIGH 1t P as packets of 16 (4x4 tiles, rtcIntersect16) %ld %.6f %.2f Mrays/s\n",
               name, pH16.hits, pH16.tsum, pH16.mrays);
        printf("#  %s: default threads (%ld hw): HIGH build_ms=%.1f MEDIUM build_ms=%.1f\n",
               name, sysconf(_SC_NPROCESSORS_ONLN), bHN, bMN);
        fflush(stdout);

        free(P.o); free(P.d); free(R.o); free(R.d);
        free(m.vf); free(m.vd); free(m.idx);
    }
    return 0;
}
