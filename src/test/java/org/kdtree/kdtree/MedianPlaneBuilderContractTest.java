package org.kdtree.kdtree;

import org.kdtree.contract.KdTreeBuilderContract;

/** The builder contract for {@link MedianPlaneBuilder} with its default settings. */
class MedianPlaneBuilderContractTest extends KdTreeBuilderContract {
    @Override protected KdTreeBuilder newBuilder() { return new MedianPlaneBuilder(); }
}
