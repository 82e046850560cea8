package org.kdtree.cli;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

/**
 * The operating-system box a student's JVM runs in: Linux namespaces through bubblewrap
 * ({@code bwrap}). Inside, the system ({@code /usr}, {@code /etc}) is read-only; the JDK, the
 * library's jars and the student's one jar are read-only under {@code /box}; the only writable
 * folder is a private {@code /tmp} of {@value #SCRATCH_MB} MB (a tmpfs, gone with the box); there
 * is no network (a network namespace of its own), no other process (a PID namespace of its own),
 * no other file: no other student's jar, no home folder, no class folder. Threads and processes
 * are bounded ({@value #TASKS}, {@code RLIMIT_NPROC} in a user namespace of the box's own, so the
 * count is the box's alone).
 *
 * <p>When the teacher is root, the box's code runs as {@code nobody} (the kernel does not bound a
 * root's threads), through {@code setpriv} and {@code unshare} (util-linux); otherwise bubblewrap
 * makes the user namespace itself, which needs unprivileged user namespaces.
 */
final class StudentBox {
    /** The box's writable scratch folder, {@code /tmp}, in MB. */
    static final int SCRATCH_MB = 64;
    /** The most threads and processes the box's code may have at once (a JVM needs about 30 of its own). */
    static final int TASKS = 256;
    /** Where the student's jar is inside the box (its file name follows). */
    static final String JAR_FOLDER = "/box/jar/";

    private static final String INSTALL = "install it with: apt-get install bubblewrap (Debian, Ubuntu), dnf install bubblewrap (Fedora)";

    private final String bwrap;
    private final boolean root;

    private StudentBox(String bwrap, boolean root) {
        this.bwrap = bwrap;
        this.root = root;
    }

    /** No box can be made here: the message says what is missing and how to install it, in one line. */
    static final class Unavailable extends Exception {
        private static final long serialVersionUID = 1L;

        Unavailable(String message) {
            super(message);
        }
    }

    /**
     * Finds bubblewrap and makes one empty box to see that it works here.
     * @return the box
     * @throws Unavailable if none can be made, saying why and what to install
     */
    static StudentBox find() throws Unavailable {
        String bwrap = onPath("bwrap");
        if (bwrap == null) throw new Unavailable("bubblewrap (bwrap) is not installed; " + INSTALL);
        boolean root = isRoot();
        if (root) for (String tool : List.of("setpriv", "unshare", "prlimit"))
            if (onPath(tool) == null) throw new Unavailable(tool + " is not installed (util-linux); install it with: apt-get install util-linux");
        if (!root && onPath("prlimit") == null) throw new Unavailable("prlimit is not installed (util-linux); install it with: apt-get install util-linux");
        StudentBox box = new StudentBox(bwrap, root);
        box.probe();
        return box;
    }

    /** Runs {@code true} in a box; a box that cannot be made says why on its standard error. */
    private void probe() throws Unavailable {
        List<String> cmd = new ArrayList<>(mounts(List.of()));
        cmd.addAll(inside());
        cmd.add("true");
        try {
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectInput(ProcessBuilder.Redirect.from(nullDevice())).start();
            String out;
            try (var in = p.getInputStream()) {
                out = new String(in.readNBytes(4000), StandardCharsets.UTF_8).strip();
            }
            if (!p.waitFor(30, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new Unavailable("bubblewrap did not start a box within 30 s");
            }
            if (p.exitValue() != 0) {
                String why = out.isEmpty() ? "exit code " + p.exitValue() : StudentRow.oneLine(out.substring(out.lastIndexOf('\n') + 1));
                throw new Unavailable("bubblewrap cannot make a box here (" + why + ")"
                        + (root ? "" : "; it needs unprivileged user namespaces: sysctl kernel.unprivileged_userns_clone=1"));
            }
        } catch (IOException e) {
            throw new Unavailable("bubblewrap cannot be run (" + e.getMessage() + "); " + INSTALL);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new Unavailable("interrupted while trying bubblewrap");
        }
    }

    /**
     * The command that runs {@code java ARGS} in a box of its own, the student's jar (fed on the
     * standard input: see {@link #jarInside}) read-only inside.
     * @param classPath the library's class path entries (jars or folders), mounted read-only as {@code /box/lib/N}
     * @param extraBinds more of bubblewrap's bind options (the class's archive of the library's classes)
     * @param jvmOptions the JVM's options (heap)
     * @param jarName the student jar's file name
     * @param mainAndArgs the main class and its arguments (the jar as {@link #jarInside})
     * @return the command
     */
    List<String> command(List<String> classPath, List<String> extraBinds, List<String> jvmOptions, String jarName, List<String> mainAndArgs) {
        List<String> binds = new ArrayList<>(List.of("--ro-bind", System.getProperty("java.home"), "/box/jdk",
                "--perms", "0755", "--dir", "/box/lib"));
        binds.addAll(extraBinds);
        List<String> inside = new ArrayList<>();
        for (int i = 0; i < classPath.size(); i++) {
            String at = "/box/lib/" + i + (Files.isDirectory(Path.of(classPath.get(i))) ? "" : ".jar");
            binds.addAll(List.of("--ro-bind", classPath.get(i), at));
            inside.add(at);
        }
        binds.addAll(List.of("--perms", "0755", "--dir", "/box/jar", "--perms", "0444", "--ro-bind-data", "0", jarInside(jarName)));
        List<String> cmd = new ArrayList<>(mounts(binds));
        cmd.addAll(inside());
        cmd.add("/box/jdk/bin/java");
        cmd.addAll(jvmOptions);
        cmd.addAll(List.of("-Duser.home=/tmp", "-Djava.io.tmpdir=/tmp", "-cp", String.join(File.pathSeparator, inside)));
        cmd.addAll(mainAndArgs);
        return cmd;
    }

    /** {@return the student's jar's path inside the box} */
    static String jarInside(String jarName) {
        return JAR_FOLDER + jarName;
    }

    /** bwrap and its mounts: the system read-only, {@code binds}, a scratch /tmp, then the root read-only. */
    private List<String> mounts(List<String> binds) {
        List<String> c = new ArrayList<>(List.of(bwrap, "--die-with-parent", "--new-session",
                "--unshare-pid", "--unshare-net", "--unshare-ipc", "--unshare-uts", "--unshare-cgroup-try"));
        if (!root) c.add("--unshare-user");
        c.addAll(List.of("--ro-bind", "/usr", "/usr", "--ro-bind", "/etc", "/etc"));
        for (String top : List.of("bin", "sbin", "lib", "lib32", "lib64", "libx32")) {
            Path p = Path.of("/" + top);
            try {
                if (Files.isSymbolicLink(p)) c.addAll(List.of("--symlink", Files.readSymbolicLink(p).toString(), "/" + top));
                else if (Files.isDirectory(p)) c.addAll(List.of("--ro-bind", "/" + top, "/" + top));
            } catch (IOException unreadable) {
                // not there to bind
            }
        }
        c.addAll(List.of("--proc", "/proc", "--dev", "/dev",
                "--perms", "1777", "--size", Long.toString((long) SCRATCH_MB << 20), "--tmpfs", "/tmp",
                "--perms", "0755", "--dir", "/box"));
        c.addAll(binds);
        c.addAll(List.of("--remount-ro", "/", "--chdir", "/tmp", "--clearenv", "--setenv", "HOME", "/tmp",
                "--setenv", "PATH", "/usr/bin:/bin", "--setenv", "LANG", "C.UTF-8", "--"));
        return c;
    }

    /** Inside the box, before the command: the bound on threads and processes (and, for a root teacher, nobody's user). */
    private List<String> inside() {
        List<String> c = new ArrayList<>();
        if (root) c.addAll(List.of("setpriv", "--reuid", "65534", "--regid", "65534", "--clear-groups", "--inh-caps=-all",
                "--bounding-set=-all", "unshare", "--user"));
        c.addAll(List.of("prlimit", "--nproc=" + TASKS));
        return c;
    }

    /** What the box stopped, from what the student's code was told (an exception's words), or "" if none of it. */
    static String stopped(String said) {
        String s = said.toLowerCase(Locale.ROOT);
        List<String> what = new ArrayList<>();
        if (s.contains("read-only file system")) what.add("a write outside its scratch folder (read-only)");
        if (s.contains("no space left on device")) what.add("its scratch folder is full (" + SCRATCH_MB + " MB)");
        if (s.contains("network is unreachable") || s.contains("unknownhostexception") || s.contains("protocol family unavailable")
                || s.contains("connection refused"))
            what.add("a connection (no network)");
        if (s.contains("unable to create native thread") || s.contains("resource temporarily unavailable"))
            what.add("a thread or process beyond the bound of " + TASKS);
        if (s.contains("nosuchfileexception") || s.contains("accessdeniedexception") || s.contains("permission denied")
                || s.contains("no such file or directory") || s.contains("directory nonexistent"))
            what.add("access to a file outside the box");
        return what.isEmpty() ? "" : "the box stopped " + String.join(", ", what);
    }

    private static String onPath(String tool) {
        String path = System.getenv("PATH");
        for (String dir : (path == null ? "/usr/bin:/bin" : path).split(File.pathSeparator)) {
            if (dir.isEmpty()) continue;
            Path p = Path.of(dir, tool);
            if (Files.isRegularFile(p) && Files.isExecutable(p)) return p.toString();
        }
        return null;
    }

    private static boolean isRoot() {
        try {
            Object uid = Files.getAttribute(Path.of("/proc/self"), "unix:uid");
            return Integer.valueOf(0).equals(uid);
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException e) {
            return false;
        }
    }

    static File nullDevice() {
        return new File("/dev/null");
    }
}
