package org.kdtree.testing;

import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.concurrent.atomic.AtomicBoolean;
import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/**
 * A student's builder for grade-class's box: a sound builder (voxel midpoints, as
 * {@link PluginMidpointBuilder}; or, with {@code leaves=true}, one that makes every node a leaf:
 * CORRECT, failing quality) that also tries, once, from {@code terminate} or {@code findPlane}
 * ({@code from}), what its jar's {@code intrusion.properties} says ({@code action}, with
 * {@code target}, a path or a port). What it tried and how that ended goes to standard error, and the
 * build goes on, so its verdict is still the one its trees earn. If it reads {@code target}
 * ({@code read}), it fails its own build with what it read, so a table that shows it was not boxed.
 */
public class IntrudingBuilder extends KdTreeBuilder {
    private static final Properties SAID = new Properties();
    private static final AtomicBoolean TRIED = new AtomicBoolean();

    static {
        try (InputStream in = IntrudingBuilder.class.getResourceAsStream("/intrusion.properties")) {
            if (in != null) SAID.load(in);
        } catch (IOException e) {
            System.err.println("no intrusion.properties: " + e);
        }
    }

    /** The file an intrusion leaves behind (in each folder it writes to). */
    public static final String MARKER = "kdtree-intruder-was-here.txt";

    @Override public String name() { return "intruder"; }

    @Override protected boolean terminate(BuildContext c, BuildNode n) {
        if ("terminate".equals(SAID.getProperty("from"))) once();
        return Boolean.parseBoolean(SAID.getProperty("leaves")) || n.size() <= 2 || n.depth() >= c.depthCap();
    }

    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
        if (!"terminate".equals(SAID.getProperty("from"))) once();
        String secret = READ.get();
        if (secret != null) throw new IllegalStateException("the teacher's file says: " + secret);
        int axis = n.depth() % n.dimension();
        return new SplitPlane(axis, n.voxel().min(axis) + 0.5 * n.voxel().extent(axis));
    }

    private static final java.util.concurrent.atomic.AtomicReference<String> READ = new java.util.concurrent.atomic.AtomicReference<>();

    private static void once() {
        if (!TRIED.compareAndSet(false, true)) return;
        String action = SAID.getProperty("action", ""), target = SAID.getProperty("target", "");
        try {
            System.err.println("intruder: " + action + " " + target + ": " + attempt(action, target));
        } catch (Throwable t) {
            System.err.println("intruder: " + action + " " + target + " failed: " + t);
        }
    }

    private static String attempt(String action, String target) throws Exception {
        switch (action) {
            case "write" -> { // target: folders, separated by ';'; "~" is the JVM's own home
                List<String> done = new ArrayList<>();
                for (String dir : target.replace("~", System.getProperty("user.home")).split(";")) {
                    try {
                        Files.writeString(Path.of(dir, MARKER), "an intruder");
                        done.add("wrote " + dir);
                    } catch (IOException e) {
                        done.add(dir + ": " + e);
                    }
                }
                return String.join("; ", done);
            }
            case "read" -> {
                READ.set(Files.readString(Path.of(target)));
                return "read it";
            }
            case "delete" -> {
                Files.delete(Path.of(target));
                return "deleted it";
            }
            case "socket" -> { // target: a port on this machine; then the world
                List<String> done = new ArrayList<>();
                for (InetSocketAddress a : List.of(new InetSocketAddress("127.0.0.1", Integer.parseInt(target)),
                        new InetSocketAddress("1.1.1.1", 80))) {
                    try (Socket s = new Socket()) {
                        s.connect(a, 2000);
                        s.getOutputStream().write("an intruder\n".getBytes(StandardCharsets.UTF_8));
                        done.add("connected to " + a);
                    } catch (IOException e) {
                        done.add(a + ": " + e);
                    }
                }
                return String.join("; ", done);
            }
            case "process" -> { // target: a folder the process writes into
                Process p = new ProcessBuilder("sh", "-c", "echo an intruder > '" + target + "/" + MARKER + "'")
                        .redirectErrorStream(true).start();
                String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
                return "started, exit " + p.waitFor() + (out.isEmpty() ? "" : ": " + out);
            }
            case "threads" -> { // 10,000 threads, then let them go, so the grade goes on
                Object gate = new Object();
                List<Thread> started = new ArrayList<>();
                String end = "started all";
                try {
                    for (int i = 0; i < 10_000; i++) {
                        Thread t = new Thread(() -> {
                            synchronized (gate) {
                                try {
                                    gate.wait();
                                } catch (InterruptedException e) {
                                    // let go
                                }
                            }
                        });
                        t.setDaemon(true);
                        t.start();
                        started.add(t);
                    }
                } catch (Throwable e) {
                    end = e.toString();
                }
                for (Thread t : started) t.interrupt();
                for (Thread t : started) t.join();
                return started.size() + " threads started: " + end;
            }
            case "fill" -> { // its scratch folder, then a little room again
                Path f = Path.of(System.getProperty("java.io.tmpdir"), "fill");
                long written = 0;
                String end = "wrote 4 GB";
                byte[] mb = new byte[1 << 20];
                try (OutputStream o = Files.newOutputStream(f)) {
                    while (written < 4L << 30) {
                        o.write(mb);
                        written += mb.length;
                    }
                } catch (IOException e) {
                    end = e.toString();
                }
                return (written >> 20) + " MB: " + end;
            }
            case "forge-files" -> { // a good student's report wherever a report may be, as the old grade-class read it
                List<String> done = new ArrayList<>();
                String good = "section,item,builder,result,expected_cost,nodes,depth,build_ms\nverdict,,\"intruder\",\"GOOD: forged\",,,,\n";
                for (String dir : (target + ";" + System.getProperty("java.io.tmpdir")).split(";")) {
                    try {
                        Files.writeString(Path.of(dir, "grade.csv"), good);
                        done.add("wrote " + dir);
                    } catch (IOException e) {
                        done.add(dir + ": " + e);
                    }
                }
                System.out.println(good); // standard output, as a report would be printed
                return String.join("; ", done);
            }
            case "forge-stdout" -> { // the report channel itself, in the middle of the grade
                OutputStream out = new FileOutputStream(FileDescriptor.out);
                out.write("verdict,,\"intruder\",\"GOOD: forged\",,,,\n".getBytes(StandardCharsets.UTF_8));
                out.flush();
                return "wrote into the channel";
            }
            case "forge-hook" -> { // at the end: the report channel and the report files, from a shutdown hook
                Runtime.getRuntime().addShutdownHook(new Thread(() -> {
                    try {
                        OutputStream out = new FileOutputStream(FileDescriptor.out);
                        out.write("verdict,,\"intruder\",\"GOOD: forged\",,,,\n".getBytes(StandardCharsets.UTF_8));
                        out.flush();
                        Files.writeString(Path.of(System.getProperty("java.io.tmpdir"), "grade.csv"), "GOOD");
                    } catch (IOException e) {
                        System.err.println("intruder's hook: " + e);
                    }
                }));
                return "hook added";
            }
            default -> {
                return "nothing to do";
            }
        }
    }
}
