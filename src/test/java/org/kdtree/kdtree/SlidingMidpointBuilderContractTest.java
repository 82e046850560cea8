package org.kdtree.kdtree;

import org.kdtree.contract.KdTreeBuilderContract;

/** The builder contract for {@link SlidingMidpointBuilder} with its default settings. */
class SlidingMidpointBuilderContractTest extends KdTreeBuilderContract {
    @Override protected KdTreeBuilder newBuilder() { return new SlidingMidpointBuilder(); }
}
