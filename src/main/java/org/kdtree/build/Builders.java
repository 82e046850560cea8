package org.kdtree.build;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;

/**
 * The builders known by name to the command line and the workbench. A student's builder
 * joins them with {@link #register}.
 */
public final class Builders {
    private static final Map<String, Supplier<? extends KdTreeBuilder>> BY_NAME = new LinkedHashMap<>();

    static {
        register("sah", SahBuilder::new);
        register("median-plane", MedianPlaneBuilder::new);
        register("object-median", ObjectMedianBuilder::new);
        register("centre-midpoint", org.kdtree.examples.CentreMidpointBuilder::new);
        register("sliding-midpoint", SlidingMidpointBuilder::new);
    }

    private Builders() {
    }

    /**
     * Makes {@code factory}'s builders available under {@code name} (replacing any before).
     *
     * @param name the builder's name, as the command line and workbench know it
     * @param factory makes a new builder with its default settings
     */
    public static synchronized void register(String name, Supplier<? extends KdTreeBuilder> factory) {
        BY_NAME.put(name, factory);
    }

    /** {@return the registered names, in registration order} */
    public static synchronized Set<String> names() {
        return java.util.Collections.unmodifiableSet(new java.util.LinkedHashSet<>(BY_NAME.keySet()));
    }

    /**
     * A new builder of that name, with its default settings.
     *
     * @param name a registered name
     * @return the new builder
     * @throws IllegalArgumentException if no builder has that name
     */
    public static synchronized KdTreeBuilder create(String name) {
        Supplier<? extends KdTreeBuilder> f = BY_NAME.get(name);
        if (f == null)
            throw new IllegalArgumentException("unknown builder '" + name + "' (known: " + String.join(", ", BY_NAME.keySet()) + ")");
        return f.get();
    }
}
