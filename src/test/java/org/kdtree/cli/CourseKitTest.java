package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.testing.PluginJars;
import org.kdtree.testing.StudentJars;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * Issue 44: the course kit where courses grade. A class graded with a roster, the starter's
 * rubric and JUnit XML (names and ids from the roster, each mismatch one line, scores that follow
 * the rubric, XML that xmllint accepts with the right failures); and Gradescope's results.json
 * of one jar of each kind (good, buggy, hanging, exiting, not a jar), its fields and types as
 * Gradescope's autograder specification gives them, its scores the rubric's.
 */
class CourseKitTest {
    private static final String T = "org.kdtree.testing.";
    private static final Path STARTER_RUBRIC = Path.of("docs/assignment/template/rubric.json");
    private static final String[] QUICK = {"--call-deadline", "1", "--build-deadline", "10"};

    @Test void aClassWithARosterARubricAndJunitXml(@TempDir Path dir) throws Exception {
        BoxTests.assumeABoxCanBeMade();
        Path jars = Files.createDirectory(dir.resolve("jars"));
        StudentJars.compile(jars, "alice.jar", "my-builder", 2, null);
        PluginJars.student(jars, "carol.jar", "Carol's login", new String[] {T + "PlaneOutsideBuilder"}, new String[0]);
        PluginJars.student(jars, "frank.jar", "Frank", new String[] {T + "ExitingBuilder"}, new String[0]);
        Path roster = Files.writeString(dir.resolve("roster.csv"),
                "file,name,id\nalice.jar,\"Smith, Alice\",s001\ncarol.jar,Carol Jones,s002\ndora.jar,Dora Lee,s004\n");
        Path csv = dir.resolve("class.csv"), md = dir.resolve("class.md"), xml = dir.resolve("class.xml");
        List<String> args = new ArrayList<>(List.of("grade-class", jars.toString(), "--roster", roster.toString(), "--rubric",
                STARTER_RUBRIC.toString(), "--junit-xml", xml.toString(), "--csv", csv.toString(), "--markdown", md.toString(), "-q",
                "--jobs", "2", "--student-heap", "128", "--student-deadline", "60"));
        args.addAll(List.of(QUICK));
        CliRun run = CliRun.of(args.toArray(String[]::new));

        assertThat(run.code()).as(run.err()).isZero();
        assertThat(run.out()).contains("roster: Dora Lee (s004): no jar dora.jar in the folder\n",
                "roster: frank.jar is not on the roster: named as before (its manifest, else its file name)\n");
        Map<String, Map<String, String>> rows = ClassGradeCommandTest.rows(Files.readString(csv, StandardCharsets.UTF_8));
        assertThat(rows.get("alice.jar")).containsEntry("student", "Smith, Alice").containsEntry("id", "s001");
        assertThat(rows.get("carol.jar")).containsEntry("student", "Carol Jones").containsEntry("id", "s002");
        assertThat(rows.get("frank.jar")).containsEntry("student", "Frank").containsEntry("id", "");
        assertThat(rows).hasSize(3);

        // alice honours the contract (50 points), earns each quality check she passes and a share of the cost's 30
        Map<String, String> alice = rows.get("alice.jar");
        assertThat(alice.get("verdict")).isIn("CORRECT", "GOOD");
        Rubric rubric = Rubric.read("--rubric", STARTER_RUBRIC);
        double expected = 50;
        for (Rubric.Item i : rubric.items())
            if (List.of("planes separate something", "leaves stop before the depth cap", "expected cost at most the median plane's").contains(i.check())
                    && !alice.get("quality_failed").contains(i.check())) expected += i.points();
        expected += rubric.items().get(rubric.items().size() - 2).earned(Double.parseDouble(alice.get("cost_vs_sah")));
        assertThat(Double.parseDouble(alice.get("score"))).isCloseTo(expected, within(0.2));   // the CSV's ratio has 2 decimals
        assertThat(Double.parseDouble(rows.get("carol.jar").get("score"))).isLessThan(50);
        assertThat(rows.get("frank.jar").get("score")).isEqualTo("0");
        assertThat(Files.readString(md)).contains("| alice.jar | Smith, Alice | s001 | my-builder |", "score (of 100)", "## Roster",
                "- roster: Dora Lee (s004): no jar dora.jar in the folder");

        XmlCheck.assertWellFormed(xml);
        Document doc = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(xml.toFile());
        NodeList suites = doc.getElementsByTagName("testsuite");
        assertThat(suites.getLength()).isEqualTo(3);
        int checks = Rubric.checks().size();
        assertThat(doc.getElementsByTagName("testcase").getLength()).isEqualTo(3 * checks);
        for (int s = 0; s < 3; s++) {
            Element suite = (Element) suites.item(s);
            NodeList cases = suite.getElementsByTagName("testcase");
            String name = suite.getAttribute("name");
            for (int c = 0; c < cases.getLength(); c++) {
                Element tc = (Element) cases.item(c);
                assertThat(tc.getAttribute("classname")).isEqualTo(name);
                NodeList failure = tc.getElementsByTagName("failure");
                String message = failure.getLength() == 0 ? null : ((Element) failure.item(0)).getAttribute("message");
                if (name.equals("Frank/frank.jar")) assertThat(message).startsWith("not graded: crashed: the JVM exited with code 42");
                if (name.equals("Carol Jones/carol.jar") && tc.getAttribute("name").equals("talk figures"))
                    assertThat(message).startsWith("FAIL, your builder's fault: ").contains("outside the voxel");
                if (name.equals("Smith, Alice/alice.jar") && c < 18) assertThat(message).as(tc.getAttribute("name")).isNull();
            }
        }
    }

    @Test void gradescopeResultsOfEachKindOfSubmission(@TempDir Path dir) throws Exception {
        BoxTests.assumeABoxCanBeMade();
        Rubric rubric = Rubric.read("--rubric", STARTER_RUBRIC);
        Path good = StudentJars.compile(dir, "good.jar", "my-builder", 2, null);
        Path buggy = PluginJars.student(dir, "buggy.jar", null, new String[] {T + "PlaneOutsideBuilder"}, new String[0]);
        Path hangs = PluginJars.student(dir, "hangs.jar", null, new String[] {T + "LoopingFindPlaneBuilder"}, new String[] {T + "Spin"});
        Path exits = PluginJars.student(dir, "exits.jar", null, new String[] {T + "ExitingBuilder"}, new String[0]);
        Path notAJar = Files.writeString(dir.resolve("notes.jar"), "my notes, not a jar");
        Object[][] kinds = {{good, 0, "pass"}, {buggy, 1, "outside the voxel"}, {hangs, 1, "did not return within 1 s"},
                {exits, Failure.BUILDER, "System.exit(42)"}, {notAJar, Failure.USAGE, "not a jar (zip) file"}};
        for (Object[] k : kinds) {
            Path jar = (Path) k[0], results = dir.resolve(jar.getFileName() + ".results.json");
            List<String> args = new ArrayList<>(List.of("grade", "--student-jar", jar.toString(), "--format", "gradescope", "-o",
                    results.toString(), "--rubric", STARTER_RUBRIC.toString(), "-q"));
            args.addAll(List.of(QUICK));
            CliRun run = CliRun.of(args.toArray(String[]::new));
            assertThat(run.code()).as(jar + ": " + run.err()).isEqualTo(k[1]);
            JsonObject r = JsonParser.parseString(Files.readString(results)).getAsJsonObject();
            assertGradescopeShape(r, jar.toString());
            JsonArray tests = r.getAsJsonArray("tests");
            assertThat(tests.size()).isEqualTo(rubric.items().size());
            double sum = 0;
            for (int i = 0; i < tests.size(); i++) {
                JsonObject t = tests.get(i).getAsJsonObject();
                Rubric.Item item = rubric.items().get(i);
                assertThat(t.get("name").getAsString()).isEqualTo(item.check());
                assertThat(t.get("max_score").getAsDouble()).isEqualTo(item.points());
                assertThat(t.get("visibility").getAsString()).isEqualTo(item.visibility());
                boolean passed = t.get("status").getAsString().equals("passed");
                if (!item.measured()) assertThat(t.get("score").getAsDouble()).as(item.check()).isEqualTo(passed ? item.points() : 0);
                sum += t.get("score").getAsDouble();
            }
            assertThat(r.get("score").getAsDouble()).isCloseTo(sum, within(1e-6));
            String all = r.toString();
            assertThat(all).as(jar.toString()).contains((String) k[2]);
            if (jar == good) {
                assertThat(r.get("score").getAsDouble()).isGreaterThanOrEqualTo(50);
                assertThat(r.getAsJsonArray("leaderboard")).hasSize(2);
            } else {
                assertThat(r.has("leaderboard")).isFalse();
                assertThat(r.get("score").getAsDouble()).isLessThan(50);
            }
        }
    }

    /** A jar that is none: exit 2 and one line, its JUnit XML every check failed saying why, no report (there is none). */
    @Test void aJarNotGradedGetsItsJunitXmlButNoReport(@TempDir Path dir) throws Exception {
        BoxTests.assumeABoxCanBeMade();
        Path notAJar = Files.writeString(dir.resolve("notes.jar"), "my notes, not a jar"), xml = dir.resolve("g.xml");
        CliRun run = CliRun.of("grade", "--student-jar", notAJar.toString(), "-o", dir.resolve("g.md").toString(), "--junit-xml",
                xml.toString(), "-q");
        assertThat(run.code()).isEqualTo(Failure.USAGE);
        assertThat(run.err().strip()).isEqualTo("error: grade notes.jar: not graded: not a jar (zip) file");
        assertThat(dir.resolve("g.md")).doesNotExist();
        XmlCheck.assertWellFormed(xml);
        assertThat(Files.readString(xml)).contains("failures=\"" + Rubric.checks().size() + "\"", "message=\"not graded: not a jar (zip) file\"");
    }

    /** The fields and types of Gradescope's results.json ("Autograder Specifications", output format). */
    static void assertGradescopeShape(JsonObject r, String what) {
        Set<String> top = Set.of("score", "execution_time", "output", "output_format", "test_output_format", "test_name_format",
                "visibility", "stdout_visibility", "extra_data", "tests", "leaderboard");
        assertThat(top).as(what).containsAll(r.keySet());
        assertThat(number(r.get("score"))).as(what + ": score").isTrue();
        assertThat(r.get("execution_time").getAsJsonPrimitive().isNumber()).isTrue();
        assertThat(r.get("execution_time").getAsDouble()).isEqualTo(Math.rint(r.get("execution_time").getAsDouble()));
        assertThat(r.get("output").getAsJsonPrimitive().isString()).isTrue();
        Set<String> visibilities = Set.of("visible", "hidden", "after_due_date", "after_published");
        for (JsonElement e : r.getAsJsonArray("tests")) {
            JsonObject t = e.getAsJsonObject();
            assertThat(Set.of("score", "max_score", "status", "name", "name_format", "number", "output", "output_format", "tags",
                    "visibility", "extra_data")).containsAll(t.keySet());
            assertThat(t.keySet()).contains("name", "score", "max_score", "output", "visibility");
            assertThat(t.get("name").getAsJsonPrimitive().isString()).isTrue();
            assertThat(number(t.get("score")) && number(t.get("max_score"))).isTrue();
            assertThat(t.get("score").getAsDouble()).isBetween(0.0, t.get("max_score").getAsDouble());
            assertThat(t.get("output").getAsJsonPrimitive().isString()).isTrue();
            assertThat(t.get("visibility").getAsString()).isIn(visibilities);
            assertThat(t.get("status").getAsString()).isIn("passed", "failed");
        }
        if (r.has("leaderboard"))
            for (JsonElement e : r.getAsJsonArray("leaderboard")) {
                JsonObject l = e.getAsJsonObject();
                assertThat(Set.of("name", "value", "order")).containsAll(l.keySet());
                assertThat(l.get("name").getAsJsonPrimitive().isString()).isTrue();
                assertThat(number(l.get("value"))).isTrue();
                assertThat(l.get("order").getAsString()).isIn("asc", "desc");
            }
    }

    private static boolean number(JsonElement e) {
        return e != null && e.isJsonPrimitive() && e.getAsJsonPrimitive().isNumber();
    }
}
