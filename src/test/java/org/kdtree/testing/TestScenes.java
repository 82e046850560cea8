package org.kdtree.testing;

import org.kdtree.check.ContractScenes;

/** The tests' name for the contract's scenes ({@link ContractScenes}): generated in code, so no test depends on files users may not have. */
public final class TestScenes extends ContractScenes {
    private TestScenes() {
    }
}
