package org.kdtree.examples;

import org.kdtree.contract.KdTreeBuilderContract;
import org.kdtree.kdtree.KdTreeBuilder;

/** The worked example of docs/write-your-own-builder.md passes the same contract as ours. */
class CentreMidpointBuilderContractTest extends KdTreeBuilderContract {
    @Override protected KdTreeBuilder newBuilder() { return new CentreMidpointBuilder(); }
}
