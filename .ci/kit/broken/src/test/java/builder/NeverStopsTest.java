package builder;

import org.kdtree.contract.KdTreeBuilderContract;
import org.kdtree.kdtree.KdTreeBuilder;

class NeverStopsTest extends KdTreeBuilderContract {
    @Override protected KdTreeBuilder newBuilder() {
        return new NeverStops();
    }
}
