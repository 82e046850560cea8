package org.kdtree.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import org.kdtree.compare.Term;
import org.kdtree.compare.TreeDistance;
import org.kdtree.compare.TreeSignature;
import org.kdtree.files.AtomicFile;
import org.kdtree.io.FileKind;
import org.kdtree.limits.Limits;
import org.kdtree.shape.Primitives;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code similar QUERY FOLDER [--top N] [BUILDER] [--cache DIR] [--csv F]}: the data sets of a
 * folder nearest to the query, by the distance of their kd-trees' signatures: the indexing use of
 * the talk's section 5.2 (docs/compare.md).
 */
@Command(name = "similar", mixinStandardHelpOptions = true,
        description = {"Rank the data sets of a folder by the distance of their kd-trees to the query's.",
                "The distance is compare-trees'; nearest first. The candidates are the folder's files of the query's kind",
                "(for a point CSV: of its extension), the query itself left out; those of another dimension, and those",
                "that cannot be read, are skipped with a note. Each file's signature is kept in a cache folder and made",
                "again only when the file's content (or the builder) changes. See docs/compare.md."})
final class SimilarCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "QUERY", description = "The data set to find the like of.")
    Path query;

    @Parameters(index = "1", paramLabel = "FOLDER", description = "The folder of data sets (its files, not its subfolders).")
    Path folder;

    @Option(names = "--top", paramLabel = "N", defaultValue = "10", description = "Print the N nearest (default: ${DEFAULT-VALUE}).")
    int top;

    @Mixin
    CompareOptions compare = new CompareOptions("every tree");

    @Option(names = "--cache", paramLabel = "DIR",
            description = "Where the signatures are kept (default: $XDG_CACHE_HOME/kdtree/signatures, else ~/.cache/kdtree/signatures).")
    Path cacheFolder;

    @Option(names = "--csv", paramLabel = "FILE", description = "Also write the whole ranking as CSV: rank,distance, each term, file.")
    Path csv;

    /** A ranked data set. */
    private record Ranked(Path file, TreeDistance distance) {
    }

    @Override public Integer call() throws Exception {
        Limits.RANKED.check("--top", top);
        if (!Files.isDirectory(folder)) throw new IllegalArgumentException("FOLDER " + folder + (Files.exists(folder) ? ": not a folder" : ": no such folder"));
        if (csv != null) {
            CommandFiles.requireWritable("--csv", csv);
            CommandFiles.requireNotInput("--csv", csv, "QUERY", query);
        }
        Primitives q = TreeData.read("QUERY", query);
        CompareOptions.TreeMaker maker = compare.maker(q);
        String builder = maker.describe();
        SignatureCache cache = new SignatureCache(cacheFolder != null ? cacheFolder : SignatureCache.defaultFolder(), builder);
        TreeSignature qs = cache.get(query, () -> TreeSignature.of(maker.build(q)));
        List<Ranked> ranked = new ArrayList<>();
        int otherKind = 0, otherData = 0, unreadable = 0;
        for (Path f : candidates()) {
            if (!sameKind(f)) { otherKind++; continue; }
            if (SameFile.same(f, query) || csv != null && SameFile.same(f, csv)) continue;
            try {
                TreeSignature s = cache.get(f, () -> TreeSignature.of(maker.build(TreeData.read("file", f))));
                if (s.dimension() != qs.dimension())   // kept in the cache all the same: the next query may be of its dimension
                    throw new IllegalArgumentException(f + ": " + s.dimension() + "-D data, the query's is " + qs.dimension() + "-D");
                ranked.add(new Ranked(f, TreeDistance.between(qs, s)));
            } catch (IllegalArgumentException e) {
                otherData++;
                System.err.println("similar: skipped " + e.getMessage());
            } catch (IOException e) {
                unreadable++;
                System.err.println("similar: skipped " + f + ": " + e.getMessage());
            }
        }
        ranked.sort(Comparator.comparingDouble((Ranked r) -> r.distance().total()).thenComparing(r -> r.file().toString()));
        System.out.printf(Locale.ROOT, "similar: %s (%s) against %d data sets of %s, builder %s%n", query, TreeData.describe(q), ranked.size(), folder, builder);
        System.out.printf(Locale.ROOT, "signatures: %d from the cache, %d made; skipped: %d of another kind, %d of other data, %d unreadable%n",
                cache.hits(), cache.made(), otherKind, otherData, unreadable);
        for (int i = 0; i < Math.min(top, ranked.size()); i++) {
            Ranked r = ranked.get(i);
            StringBuilder terms = new StringBuilder();
            for (Term t : Term.values()) terms.append(String.format(Locale.ROOT, "  %s %.3f", t.label(), r.distance().term(t)));
            System.out.printf(Locale.ROOT, "%3d  %.4f  %s %s%n", i + 1, r.distance().total(), r.file(), terms);
        }
        if (csv != null) AtomicFile.writeText(csv, out -> {
            StringBuilder header = new StringBuilder("rank,distance");
            for (Term t : Term.values()) header.append(',').append(t.label());
            out.write(header.append(",file\n").toString());
            for (int i = 0; i < ranked.size(); i++) {
                Ranked r = ranked.get(i);
                StringBuilder row = new StringBuilder(String.format(Locale.ROOT, "%d,%.6f", i + 1, r.distance().total()));
                for (Term t : Term.values()) row.append(String.format(Locale.ROOT, ",%.6f", r.distance().term(t)));
                out.write(row.append(',').append(csvField(r.file().toString())).append('\n').toString());
            }
        });
        return 0;
    }

    /** The folder's regular files, by name. */
    private List<Path> candidates() throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.filter(Files::isRegularFile).sorted().toList();
        }
    }

    /** Whether a file is of the query's kind: its scene kind, or for a point CSV (no scene kind) its extension. */
    private boolean sameKind(Path f) {
        FileKind kind = FileKind.of(query);
        if (kind != null) return FileKind.of(f) == kind;
        if (FileKind.of(f) != null) return false;
        return extension(f).equals(extension(query));
    }

    private static String extension(Path f) {
        String name = f.getFileName().toString().toLowerCase(Locale.ROOT);
        int dot = name.lastIndexOf('.');
        return dot > 0 ? name.substring(dot) : "";
    }

    private static String csvField(String s) {
        return s.contains(",") || s.contains("\"") ? '"' + s.replace("\"", "\"\"") + '"' : s;
    }
}
