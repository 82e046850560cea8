package builder;

import org.kdtree.build.KdTreeBuilder;
import org.kdtree.contract.KdTreeBuilderQualityContract;

class PlanesOnTheFaceQualityTest extends KdTreeBuilderQualityContract {
    @Override protected KdTreeBuilder newBuilder() {
        return new PlanesOnTheFace();
    }
}
