package builder;

import org.kdtree.contract.KdTreeBuilderContract;
import org.kdtree.kdtree.KdTreeBuilder;

/** The builder contract, run on your builder: every check of it is a test. */
class MyBuilderTest extends KdTreeBuilderContract {
    @Override protected KdTreeBuilder newBuilder() {
        return new MyBuilder();
    }
}
