package org.kdtree.cli;

import org.kdtree.kdtree.Supervisor;
import org.kdtree.limits.Deadlines;
import org.kdtree.limits.Limits;
import picocli.CommandLine.Option;

/**
 * How long a plug-in builder may take (a picocli mixin): {@code --call-deadline} for one call of
 * its terminate or findPlane, past which it is reported as hung, and {@code --build-deadline}
 * for the whole build, past which it is reported as slow. The library's own builders are not
 * supervised by the commands that measure them; {@code grade} supervises every builder.
 */
final class DeadlineOptions {
    @Option(names = "--call-deadline", paramLabel = "SECONDS",
            description = "A plug-in builder's terminate or findPlane call that takes longer is stopped and reported as hung "
                    + "(default: 60 s; grade and grade-class: 10 s; 0.1 to 3600).")
    Double call;

    @Option(names = "--build-deadline", paramLabel = "SECONDS",
            description = "A plug-in builder's build that takes longer is stopped and reported as slow "
                    + "(default: 600 s; grade and grade-class: 30 s; 0.1 to 86400).")
    Double build;

    /** {@return the deadlines given, each checked against its limit, or {@code defaults}' where not given} */
    Deadlines deadlines(Deadlines defaults) {
        if (call != null) Limits.CALL_DEADLINE.check("--call-deadline", call);
        if (build != null) Limits.BUILD_DEADLINE.check("--build-deadline", build);
        return defaults.with(call, build);
    }

    /** {@return the supervisor of the commands that build with one builder: plug-ins supervised, the library's own trusted} */
    Supervisor supervisor() {
        return Supervisor.of(deadlines(Deadlines.COMMAND_LINE)).trustingTheLibrary();
    }
}
