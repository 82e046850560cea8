package org.kdtree.build;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.function.Supplier;

/**
 * The builders known by name to the command line and the workbench: the library's own, then
 * every builder that a jar on the class path lists in
 * {@code META-INF/services/org.kdtree.build.KdTreeBuilder} (found with {@link ServiceLoader};
 * each needs a public no-argument constructor and is known by its {@link KdTreeBuilder#name()}).
 * So a student's builder joins them by being on the class path, with no code of the library
 * naming it; {@link #register} adds one from code.
 */
public final class Builders {
    private static final Map<String, Supplier<? extends KdTreeBuilder>> BY_NAME = new LinkedHashMap<>();

    static {
        register("sah", SahBuilder::new);
        register("median-plane", MedianPlaneBuilder::new);
        register("object-median", ObjectMedianBuilder::new);
        register("sliding-midpoint", SlidingMidpointBuilder::new);
        for (ServiceLoader.Provider<KdTreeBuilder> p : ServiceLoader.load(KdTreeBuilder.class).stream().toList())
            register(p.get().name(), () -> newInstance(p.type()));
    }

    /** A new builder of a class found by the service loader (which checked its public no-argument constructor). */
    private static KdTreeBuilder newInstance(Class<? extends KdTreeBuilder> type) {
        try {
            return type.getConstructor().newInstance();
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot make a " + type.getName() + ": " + e, e);
        }
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
