package org.kdtree.kdtree;

import org.kdtree.geom.SplitPlane;

/** The {@link BuilderFault}s the recursion itself finds: a call that threw, a plane it cannot use. */
final class BuilderFaults {
    private BuilderFaults() {
    }

    /** {@code method} threw {@code e} on {@code node}. A plane refused by {@link SplitPlane}'s checks is a bad answer. */
    static BuilderFault threw(KdTreeBuilder b, String method, BuildNode node, Throwable e) {
        if (e instanceof BuilderFault f) return f;
        String where = whereInBuilder(b, e);
        if (e instanceof IllegalArgumentException && madeBy(e, SplitPlane.class))
            return new BuilderFault(b.name(), BuilderFault.Kind.BAD_ANSWER, method, node.depth(), node.size(),
                    "made an impossible plane (" + e.getMessage() + ")" + where,
                    "a plane needs an axis >= 0 and a finite position inside the node's voxel", e);
        String hint = BuilderFault.TERMINATE.equals(method)
                ? "terminate must answer, without throwing, for every node (even an empty one)"
                : "findPlane must return a plane for every node that terminate does not make a leaf";
        return new BuilderFault(b.name(), BuilderFault.Kind.THREW, method, node.depth(), node.size(),
                "threw " + e.getClass().getSimpleName() + (e.getMessage() != null ? " (" + e.getMessage() + ")" : "") + where,
                hint, e);
    }

    /** findPlane returned a plane the recursion cannot use: {@code what} it did, and the rule. */
    static BuilderFault badPlane(KdTreeBuilder b, BuildNode node, String what, String rule) {
        return new BuilderFault(b.name(), BuilderFault.Kind.BAD_ANSWER, BuilderFault.FIND_PLANE, node.depth(), node.size(), what,
                rule, null);
    }

    /** Whether {@code e} was thrown inside {@code type}'s code (its top frame). */
    private static boolean madeBy(Throwable e, Class<?> type) {
        StackTraceElement[] s = e.getStackTrace();
        return s.length > 0 && s[0].getClassName().equals(type.getName());
    }

    /** " at Class.method(File:line)" for the deepest frame of the builder's own classes, or "" if none. */
    private static String whereInBuilder(KdTreeBuilder b, Throwable e) {
        for (StackTraceElement f : e.getStackTrace())
            for (Class<?> c = b.getClass(); c != null && c != KdTreeBuilder.class; c = c.getSuperclass())
                if (f.getClassName().equals(c.getName()) || f.getClassName().startsWith(c.getName() + "$"))
                    return " at " + f;
        return "";
    }
}
