package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.check.QualityChecks;
import org.kdtree.testing.StudentJars;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * Issue 44, items 1, 4 and 5 without a student's JVM: a rubric scores a grade's checks (the
 * pass/fail ones, and the measured ones on a straight line between full_at and zero_at); the JUnit
 * XML of scored grades is well formed, one test case per check, a failure per check lost; a bad
 * rubric or roster is one line naming the field or line, exit 2, before any grading.
 */
class RubricTest {
    private static final String RUBRIC = """
            {"title": "for the test", "visibility": "after_due_date", "checks": {
              "talk figures": {"points": 4, "visibility": "visible"},
              "stops before the depth cap": {"points": 3},
              "expected cost at most the median plane's": {"points": 5},
              "expected cost vs the SAH": {"points": 10, "full_at": 1.0, "zero_at": 2.0}
            }}""";

    @Test void aRubricScoresEachCheckAndTheCostRatioOnAStraightLine(@TempDir Path dir) throws Exception {
        Rubric rubric = Rubric.read("--rubric", write(dir, "r.json", RUBRIC));
        assertThat(rubric.maxScore()).isEqualTo(22);
        // the contract broken (talk figures): the quality tier was not run, no tree was measured; the cap check passes
        Report broken = report("builder x: findPlane chose x0 = 9, outside the voxel", 1);
        Scorecard card = Scorecard.of(rubric, StudentRow.parse("x.jar", "X", broken.csv(), 3, "bubblewrap"), broken);
        assertThat(card.checks()).extracting(Scorecard.Scored::check).containsExactlyElementsOf(Rubric.checks());
        assertThat(scored(card, "talk figures").score()).isZero();
        assertThat(scored(card, "talk figures").output()).startsWith("FAIL, your builder's fault: builder x: findPlane chose");
        assertThat(scored(card, "talk figures").visibility()).isEqualTo("visible");
        assertThat(scored(card, "stops before the depth cap").score()).isEqualTo(3);
        assertThat(scored(card, "stops before the depth cap").visibility()).isEqualTo("after_due_date");
        assertThat(scored(card, "empty scene").max()).isZero();   // not in the rubric: worth nothing, still listed
        assertThat(scored(card, "expected cost at most the median plane's").output()).startsWith("not run: ");
        assertThat(scored(card, Rubric.COST).output()).startsWith("not measured: ");
        assertThat(card.score()).isEqualTo(3);
        // sound, its trees 1.5 times the SAH's cost: half of the cost's 10 points, on the line from 1.0 (all) to 2.0 (none)
        assertThat(score(rubric, 1.5)).isEqualTo(4 + 3 + 5 + 5);
        assertThat(score(rubric, 0.9)).isEqualTo(22);
        assertThat(score(rubric, 1.8)).isCloseTo(12 + 2, within(1e-9));
        assertThat(score(rubric, 2.5)).isEqualTo(12);
        Report sound = report(null, 1.5);
        assertThat(scored(Scorecard.of(rubric, StudentRow.parse("y.jar", "Y", sound.csv(), 3, "bubblewrap"), sound), Rubric.COST).output())
                .contains("1.50 times the library's SAH's", "5 of 10");
    }

    private static double score(Rubric rubric, double costOverSah) {
        Report r = report(null, costOverSah);
        return Scorecard.of(rubric, StudentRow.parse("y.jar", "Y", r.csv(), 3, "bubblewrap"), r).score();
    }

    @Test void aJarNotGradedScoresNothingAndEveryCheckSaysWhy() {
        StudentRow row = StudentRow.failed("judy.jar", "judy", "not graded: not a jar (zip) file", 0.2, "bubblewrap");
        Scorecard card = Scorecard.of(Rubric.onePointEach(), row, null);
        assertThat(card.score()).isZero();
        assertThat(card.maxScore()).isEqualTo(Rubric.passFailChecks().size());
        assertThat(card.checks()).allSatisfy(c -> assertThat(c.output()).isEqualTo("not graded: not a jar (zip) file"));
    }

    @Test void junitXmlIsWellFormedWithOneCasePerCheckAndAFailurePerCheckLost(@TempDir Path dir) throws Exception {
        Report broken = report("builder x: <findPlane> & \"threw\"\nat line 2", 1.5), sound = report(null, 0.9);
        List<Scorecard> cards = List.of(
                Scorecard.of(Rubric.onePointEach(), StudentRow.parse("x.jar", "Ada", broken.csv(), 3, "bubblewrap").named("Ada", "17"), broken),
                Scorecard.of(Rubric.onePointEach(), StudentRow.parse("y.jar", "Bob", sound.csv(), 3, "bubblewrap"), sound),
                Scorecard.of(Rubric.onePointEach(), StudentRow.failed("z.jar", "z", "crashed: the JVM exited with code 3", 1, "bubblewrap"), null));
        String xml = JunitXml.of(cards);
        Path file = write(dir, "grades.xml", xml);
        XmlCheck.assertWellFormed(file);
        Document doc = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8)));
        NodeList suites = doc.getElementsByTagName("testsuite");
        assertThat(suites.getLength()).isEqualTo(3);
        int checks = Rubric.checks().size();
        assertThat(doc.getElementsByTagName("testcase").getLength()).isEqualTo(3 * checks);
        Element ada = (Element) suites.item(0);
        assertThat(ada.getAttribute("name")).isEqualTo("Ada/x.jar");
        assertThat(failed(ada)).containsExactly("talk figures", "planes separate something", "leaves stop before the depth cap",
                "expected cost at most the median plane's");
        assertThat(((Element) ada.getElementsByTagName("failure").item(0)).getAttribute("message"))
                .isEqualTo("FAIL, your builder's fault: builder x: <findPlane> & \"threw\"");
        assertThat(xml).contains("<property name=\"id\" value=\"17\"/>");
        assertThat(failed((Element) suites.item(1))).isEmpty();
        assertThat(failed((Element) suites.item(2))).hasSize(checks);   // not graded: every check lost
        assertThat(((Element) doc.getElementsByTagName("testsuites").item(0)).getAttribute("failures")).isEqualTo(Integer.toString(4 + checks));
    }

    @Test void aBadRubricIsOneLineNamingTheFieldBeforeAnyGrading(@TempDir Path dir) throws Exception {
        String[][] cases = {
                {"{\"checks\": {\"talk figure\": {\"points\": 2}}}", "checks.\"talk figure\": no such check; the checks are: talk figures, "},
                {"{\"checks\": {\"talk figures\": {\"points\": -1}}}", "checks.\"talk figures\".points: must be from 0 to 1000000, got -1"},
                {"{\"checks\": {\"talk figures\": {\"points\": \"two\"}}}", "checks.\"talk figures\".points: must be a number, got \"two\""},
                {"{\"checks\": {\"talk figures\": {\"points\": 2, \"visibility\": \"students\"}}}",
                        "checks.\"talk figures\".visibility: must be one of visible, hidden, after_due_date, after_published, got \"students\""},
                {"{\"checks\": {\"expected cost vs the SAH\": {\"points\": 2, \"full_at\": 2, \"zero_at\": 1}}}",
                        "checks.\"expected cost vs the SAH\".zero_at: must be greater than full_at (2.0), got 1.0"},
                {"{\"checks\": {\"talk figures\": {\"points\": 2, \"full_at\": 1}}}", "checks.\"talk figures\".full_at: no such field"},
                {"{\"check\": {}}", "check: no such field; the rubric takes checks, title, visibility"},
                {"{\"checks\": {\"talk figures\": {\"points\": 2},}}", "not a JSON rubric ("},
                {"{\"checks\": {}} // the points\n", "not a JSON rubric (malformed JSON at line 1 column "},
                {"", "not a JSON rubric ("},
        };
        for (String[] c : cases) {
            Path bad = write(dir, "bad.json", c[0]);
            CliRun run = CliRun.of("grade", "-b", "median-plane", "--rubric", bad.toString(), "-q");
            assertThat(run.code()).as(c[0]).isEqualTo(Failure.USAGE);
            assertThat(run.err().strip().lines()).as(c[0]).hasSize(1);
            assertThat(run.err().strip()).as(c[0]).startsWith("error: --rubric " + bad + ": " + c[1]);
            assertThat(run.out()).as("nothing graded").isEmpty();
        }
    }

    @Test void theStartersRubricIsARubricOfEveryCheck() {
        Rubric starter = Rubric.read("--rubric", Path.of("docs/assignment/template/rubric.json"));
        for (Rubric.Item i : starter.items())   // build times are reported by the student's JVM: worth nothing by default
            if (!i.check().equals(Rubric.TIME)) assertThat(i.points()).as(i.check()).isPositive();
        assertThat(starter.maxScore()).isEqualTo(100);
    }

    @Test void aBadRosterIsOneLineNamingTheLineBeforeAnyGrading(@TempDir Path dir) throws Exception {
        Path jars = Files.createDirectory(dir.resolve("jars"));
        StudentJars.compile(jars, "alice.jar", "my-builder", 2, null);
        String[][] cases = {
                {"name,file,id\nalice.jar,Alice,1\n", ":1: the first line must be the header file,name,id, got \"name,file,id\""},
                {"", ":1: the first line must be the header file,name,id, got an empty file"},
                {"file,name,id\nalice.jar,Alice,1\nbob.jar,Bob,2\nalice.jar,Alice B,3\n", ":4: alice.jar is listed twice (line 2 too)"},
                {"file,name,id\nalice.jar,Alice\n", ":2: a line has 3 fields (file,name,id), this one has 2"},
                {"file,name,id\nalice,Alice,1\n", ":2: the file must be a jar's name in the class folder, such as alice.jar, got \"alice\""},
        };
        for (String[] c : cases) {
            Path roster = write(dir, "roster.csv", c[0]);
            CliRun run = CliRun.of("grade-class", jars.toString(), "--roster", roster.toString(), "--csv", dir.resolve("c.csv").toString(),
                    "--markdown", dir.resolve("c.md").toString(), "-q");
            assertThat(run.code()).as(c[0]).isEqualTo(Failure.USAGE);
            assertThat(run.err().strip()).as(c[0]).isEqualTo("error: --roster " + roster + c[1]);
            assertThat(dir.resolve("c.csv")).doesNotExist();
        }
        CliRun none = CliRun.of("grade-class", jars.toString(), "--roster", dir.resolve("none.csv").toString(), "-q");
        assertThat(none.err().strip()).isEqualTo("error: --roster " + dir.resolve("none.csv") + ": no such file");
    }

    /** A grade of one course scene: the contract's checks (the first failing if {@code failure}), then the quality tier if it held. */
    static Report report(String failure, double costOverSah) {
        List<GradeCommand.Check> contract = new ArrayList<>(), quality = new ArrayList<>();
        for (String c : Rubric.passFailChecks()) {
            if (QualityChecks.NAMES.contains(c)) continue;
            contract.add(new GradeCommand.Check(c, contract.isEmpty() ? failure : null, null));
        }
        List<GradeCommand.Row> rows = new ArrayList<>();
        if (failure == null) {
            for (String q : QualityChecks.NAMES) quality.add(new GradeCommand.Check(q, null, null));
            rows.add(new GradeCommand.Row("cornell-box", "x", 100 * costOverSah, 11, 3, 2));
            rows.add(new GradeCommand.Row("cornell-box", "median-plane", 200, 11, 3, 1));
            rows.add(new GradeCommand.Row("cornell-box", "object-median", 150, 11, 3, 1));
            rows.add(new GradeCommand.Row("cornell-box", "sah", 100, 11, 3, 4));
        }
        return new Report("x", contract, quality, rows, GradeRun.verdict(contract, quality, rows));
    }

    private static Scorecard.Scored scored(Scorecard card, String check) {
        return card.checks().stream().filter(c -> c.check().equals(check)).findFirst().orElseThrow();
    }

    private static List<String> failed(Element suite) {
        List<String> names = new ArrayList<>();
        NodeList cases = suite.getElementsByTagName("testcase");
        for (int i = 0; i < cases.getLength(); i++) {
            Element c = (Element) cases.item(i);
            if (c.getElementsByTagName("failure").getLength() > 0) names.add(c.getAttribute("name"));
        }
        return names;
    }

    private static Path write(Path dir, String name, String text) throws Exception {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
    }
}
