package org.kdtree.cli;

import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kdtree.compare.Term;
import org.kdtree.compare.TreeDistance;
import org.kdtree.compare.TreeSignature;
import org.kdtree.files.AtomicFile;
import org.kdtree.gui.TreeComparisonPicture;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Primitives;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code compare-trees A B [BUILDER] [--csv F] [--chart F.png]}: the distance between two data
 * sets' kd-trees and each of its terms (the talk's section 5.2; docs/compare.md).
 */
@Command(name = "compare-trees", mixinStandardHelpOptions = true,
        description = {"Compare two data sets by comparing their kd-trees.",
                "Builds a tree over each (the same builder), takes each tree's signature (leaf volumes, split positions,",
                "depth profile, leaf depths on a common grid; normalised to the root, so a shifted or scaled copy is at",
                "distance 0) and prints the distance in [0, 1] and its terms. A and B: point CSVs (as knn reads them),",
                ".scene2d 2-D scenes, OBJ meshes or JSON scenes, both of one kind and dimension. See docs/compare.md."})
final class CompareTreesCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "A", description = "The first data set.")
    Path fileA;

    @Parameters(index = "1", paramLabel = "B", description = "The second data set, of A's kind and dimension.")
    Path fileB;

    @Mixin
    CompareOptions compare = new CompareOptions("both trees");

    @Option(names = "--csv", paramLabel = "FILE", description = "Also write the terms as CSV: term,weight,value (and the total).")
    Path csv;

    @Option(names = "--chart", paramLabel = "FILE.png", description = "Also draw the two trees side by side and where their leaf depths differ (PNG).")
    Path chart;

    @Override public Integer call() throws Exception {
        for (Path out : new Path[] {csv, chart}) {
            if (out == null) continue;
            String option = out == csv ? "--csv" : "--chart";
            CommandFiles.requireWritable(option, out);
            CommandFiles.requireNotInput(option, out, "A", fileA);
            CommandFiles.requireNotInput(option, out, "B", fileB);
        }
        if (csv != null && chart != null && SameFile.same(csv, chart))
            throw new IllegalArgumentException("--csv and --chart are the same file (" + csv + "); give two");
        Primitives a = TreeData.read("A", fileA), b = TreeData.read("B", fileB);
        TreeData.requireComparable("A", fileA, a, "B", fileB, b);
        CompareOptions.TreeMaker maker = compare.maker(a);
        String builder = maker.describe();
        KdTree treeA = maker.build(a), treeB = maker.build(b);
        TreeSignature sa = TreeSignature.of(treeA), sb = TreeSignature.of(treeB);
        TreeDistance d = TreeDistance.between(sa, sb);
        System.out.printf(Locale.ROOT, "compare-trees: %s, %s, builder %s%n", fileA, TreeData.describe(a), builder);
        System.out.printf(Locale.ROOT, "           vs %s, %s%n", fileB, TreeData.describe(b));
        System.out.printf(Locale.ROOT, "distance %.4f%n", d.total());
        for (Term t : Term.values())
            System.out.printf(Locale.ROOT, "  %-10s %.4f  (weight %.2f) %s%n", t.label(), d.term(t), t.weight(), t.help());
        System.out.printf(Locale.ROOT, "trees: %d and %d leaves, depth up to %d and %d%n", sa.leaves(), sb.leaves(), sa.maxDepth(), sb.maxDepth());
        if (csv != null) AtomicFile.writeText(csv, out -> {
            out.write("term,weight,value\n");
            for (Term t : Term.values()) out.write(String.format(Locale.ROOT, "%s,%.4f,%.6f%n", t.label(), t.weight(), d.term(t)));
            out.write(String.format(Locale.ROOT, "total,1,%.6f%n", d.total()));
        });
        if (chart != null)
            TreeComparisonPicture.write(chart, new TreeComparisonPicture.Side("A " + fileA.getFileName(), a, treeA, sa),
                    new TreeComparisonPicture.Side("B " + fileB.getFileName(), b, treeB, sb), d, maker.spec().builder());
        return 0;
    }
}
