package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** Issue 46, item 5: the SPEC line stays alone on stdout for scripts, its columns named on stderr. */
class RaycastColumnsTest {
    @Test void theSpecLineComesWithItsColumnsNamed() {
        CliRun r = CliRun.of("raycast", "scenes/meshes/mtl-demo.obj", "--runs", "1", "--warmup", "0", "-q");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out().lines()).hasSize(1);
        String[] values = r.out().strip().split(" ");
        String header = r.err().lines().filter(l -> l.startsWith("# system ")).findFirst().orElseThrow();
        String[] names = header.substring(2).split(" ");
        assertThat(names).hasSameSizeAs(values).startsWith("system", "mesh", "tris", "build_ms").endsWith("R_mrays");
        assertThat(values[0]).isEqualTo("kdtree-sah");
        assertThat(r.err().indexOf(header)).as("the names before the other notes").isLessThan(r.err().indexOf("# path:"));
    }
}
