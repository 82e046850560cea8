package org.kdtree.check;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * Issue 46, item 9: the starter's {@code findPlane} comment said "strictly inside node.voxel()"
 * where the handout (and the contract) allow a plane on the voxel's face: both now say the same.
 */
class StarterSaysWhatTheContractChecksTest {
    @Test void theStartersFindPlaneCommentAllowsAPlaneOnTheVoxelsFaceAsTheHandoutDoes() throws IOException {
        String starter = Files.readString(Path.of("docs/assignment/template/src/main/java/builder/MyBuilder.java"));
        String handout = Files.readString(Path.of("docs/write-your-own-builder.md"));
        assertThat(handout).contains("a plane on the voxel's face is allowed but useless");
        assertThat(starter).doesNotContain("strictly inside").contains("on its face is allowed but useless");
    }
}
