package builder;

import org.kdtree.contract.KdTreeBuilderQualityContract;
import org.kdtree.kdtree.KdTreeBuilder;

class PlanesOnTheFaceQualityTest extends KdTreeBuilderQualityContract {
    @Override protected KdTreeBuilder newBuilder() {
        return new PlanesOnTheFace();
    }
}
