package org.kdtree.kdtree;

import org.kdtree.contract.KdTreeBuilderContract;

/** The builder contract for {@link SahBuilder} with its default settings. */
class SahBuilderContractTest extends KdTreeBuilderContract {
    @Override protected KdTreeBuilder newBuilder() { return new SahBuilder(); }
}
