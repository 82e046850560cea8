import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.kdtree.files.CsvFields;

/**
 * Compares two grade-class tables (CSV) row by row, by jar file: every column from the student to
 * the cost ratios must agree (times, which vary from run to run, are left out). Prints each
 * difference; exits 1 if there is one.
 *
 * <p>{@code java -cp target/kdtree.jar src/bench/grade-class/SameGrades.java CLASS.csv ALONE.csv}: every row of ALONE
 * (the jars graded one at a time) is looked up in CLASS (the whole class graded at once).
 */
public class SameGrades {
    private static final List<String> COMPARED = List.of("student", "builder", "verdict", "first_failure", "quality_failed",
            "problem", "cost_vs_median", "cost_vs_sah");

    public static void main(String[] args) throws Exception {
        Map<String, Map<String, String>> all = rows(Path.of(args[0])), alone = rows(Path.of(args[1]));
        int differences = 0;
        for (var e : alone.entrySet()) {
            Map<String, String> inClass = all.get(e.getKey());
            if (inClass == null) {
                System.out.println(e.getKey() + ": not in " + args[0]);
                differences++;
                continue;
            }
            for (String c : COMPARED)
                if (!e.getValue().get(c).equals(inClass.get(c))) {
                    System.out.println(e.getKey() + ": " + c + " alone \"" + e.getValue().get(c) + "\", in the class \"" + inClass.get(c) + "\"");
                    differences++;
                }
        }
        System.out.println(alone.size() + " jars graded alone, " + differences + " differences from the class's grades");
        System.exit(differences == 0 ? 0 : 1);
    }

    static Map<String, Map<String, String>> rows(Path csv) throws Exception {
        List<String> lines = Files.readAllLines(csv);
        List<String> header = CsvFields.of(lines.get(0));
        Map<String, Map<String, String>> rows = new HashMap<>();
        for (String line : lines.subList(1, lines.size())) {
            List<String> f = CsvFields.of(line);
            Map<String, String> row = new HashMap<>();
            for (int i = 0; i < header.size(); i++) row.put(header.get(i), i < f.size() ? f.get(i) : "");
            rows.put(row.get("file"), row);
        }
        return rows;
    }
}
