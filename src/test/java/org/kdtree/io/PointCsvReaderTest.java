package org.kdtree.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.shape.PointsKd;

class PointCsvReaderTest {
    @TempDir Path dir;

    private static PointsKd read(String text) throws Exception {
        return PointCsvReader.read(new StringReader(text), "pts.csv");
    }

    @Test void readsPointsSkippingBlankAndCommentLines() throws Exception {
        PointsKd p = read("# x,y,z\n0,1,2\n\n  \n -1.5 , 2e3,0.25\n#end\n3,4,5");
        assertThat(p.dimension()).isEqualTo(3);
        assertThat(p.size()).isEqualTo(3);
        assertThat(p.coord(1, 0)).isEqualTo(-1.5);
        assertThat(p.coord(1, 1)).isEqualTo(2000);
        assertThat(p.coord(2, 2)).isEqualTo(5);
    }

    @Test void readsOneDimensionalAndWideFiles() throws Exception {
        assertThat(read("1\n2\n3\n").dimension()).isEqualTo(1);
        assertThat(read("1,2,3,4,5,6,7,8,9,10\n").dimension()).isEqualTo(10);
    }

    @Test void aWrongCountNamesTheLineAndTheExpectedCount() {
        assertThatThrownBy(() -> read("0,1\n# c\n2,3,4\n")).isInstanceOf(SceneFormatException.class)
                .hasMessage("pts.csv:3: a point needs 2 coordinates, as on line 1, got 3");
    }

    @Test void coordinatesOutsideTheQueriesRangeAreRefusedWithTheLine() {
        assertThatThrownBy(() -> read("0,1\n2,1e200\n")).isInstanceOf(SceneFormatException.class)
                .hasMessageStartingWith("pts.csv:2: the coordinate 1e200 is outside the supported range -1e100 .. 1e100");
        assertThatThrownBy(() -> read("0,0\n1e-200,0\n")).isInstanceOf(SceneFormatException.class)
                .hasMessageStartingWith("pts.csv: the points span only 1.0E-200: the smallest supported extent is 1e-100");
    }

    @Test void aFieldThatIsNotANumberNamesTheLine() {
        assertThatThrownBy(() -> read("0,1\n2,x\n")).isInstanceOf(SceneFormatException.class)
                .hasMessage("pts.csv:2: 'x' is not a number");
        assertThatThrownBy(() -> read("0,1\n2,\n")).hasMessage("pts.csv:2: an empty field where a coordinate belongs");
        assertThatThrownBy(() -> read("0 1\n")).hasMessage("pts.csv:1: '0 1' is not a number");
    }

    @Test void aNonFiniteCoordinateNamesTheLine() {
        assertThatThrownBy(() -> read("0,1\n\nNaN,1\n")).hasMessage("pts.csv:3: coordinate NaN is not finite");
        assertThatThrownBy(() -> read("1e999,1\n")).hasMessage("pts.csv:1: coordinate 1e999 is not finite");
    }

    @Test void aFileWithoutPointsIsAnError() {
        assertThatThrownBy(() -> read("# nothing\n\n")).isInstanceOf(SceneFormatException.class)
                .hasMessageStartingWith("pts.csv: no points");
    }

    @Test void filesAreNamedInErrors() throws Exception {
        Path f = dir.resolve("q.csv");
        Files.writeString(f, "1,2\n3\n");
        assertThatThrownBy(() -> PointCsvReader.read(f)).hasMessage(f + ":2: a point needs 2 coordinates, as on line 1, got 1");
        assertThatThrownBy(() -> PointCsvReader.read(dir.resolve("missing.csv"))).hasMessageContaining("no such file");
    }
}
