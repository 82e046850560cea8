package org.kdtree.kdtree;

import org.kdtree.contract.KdTreeBuilderContract;

/** The builder contract for {@link ObjectMedianBuilder} with its default settings. */
class ObjectMedianBuilderContractTest extends KdTreeBuilderContract {
    @Override protected KdTreeBuilder newBuilder() { return new ObjectMedianBuilder(); }
}
