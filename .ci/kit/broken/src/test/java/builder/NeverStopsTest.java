package builder;

import org.kdtree.build.KdTreeBuilder;
import org.kdtree.contract.KdTreeBuilderContract;

class NeverStopsTest extends KdTreeBuilderContract {
    @Override protected KdTreeBuilder newBuilder() {
        return new NeverStops();
    }
}
