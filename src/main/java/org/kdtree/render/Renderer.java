package org.kdtree.render;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayQuery;
import org.kdtree.scene.Scene;

/**
 * Renders a scene in square tiles over a pool of threads. Each thread takes the next tile, in
 * an order spread over the image ({@link TileOrder}), until none is left, with its own {@link
 * Tracer} and so its own {@link RayQuery}. Every pixel is seeded on its own, so the image
 * depends neither on the number of threads nor on the order of the tiles.
 */
public final class Renderer {
    /**
     * @param threads         worker threads (at least 1)
     * @param tileSize        tile edge in pixels
     * @param progress        told each time a tile is finished, or null
     * @param recordPixelRays whether to keep per-pixel ray counts by kind (tests)
     * @param stop            asked before each tile whether to stop (the workbench's Stop), or null
     * @param blocks          whether the block tracer is asked for wherever the structure's packet loop traces packets together, repaid or not
     */
    public record Options(int threads, int tileSize, TileListener progress, boolean recordPixelRays, BooleanSupplier stop, boolean blocks) {
        /** {@return all cores, 16-pixel tiles, no progress bar, no per-pixel counts, never stopped, blocks only where they repay} */
        public static Options defaults() {
            return new Options(Runtime.getRuntime().availableProcessors(), 16, null, false, null, false);
        }

        /**
         * {@return these options, stopping when {@code s} says so}
         *
         * @param s asked before each tile; true stops the render, the tiles done so far kept
         */
        public Options withStop(BooleanSupplier s) { return new Options(threads, tileSize, progress, recordPixelRays, s, blocks); }

        /**
         * {@return these options with {@code n} threads}
         *
         * @param n the number of threads
         */
        public Options withThreads(int n) { return new Options(n, tileSize, progress, recordPixelRays, stop, blocks); }
        /**
         * {@return these options reporting progress to {@code p}}
         *
         * @param p told of each finished tile
         */
        public Options withProgress(TileListener p) { return new Options(threads, tileSize, p, recordPixelRays, stop, blocks); }
        /** {@return these options with per-pixel ray counts recorded} */
        public Options recordingPixelRays() { return new Options(threads, tileSize, progress, true, stop, blocks); }

        /**
         * {@return these options with the block tracer asked for}: 8 x 8 pixels at a time, their rays
         * in packets, wherever the structure's packet loop traces a packet's rays together, even where
         * it does not repay it in renders ({@link PacketQuery#repaysBlocks}): to measure it; the same image
         */
        public Options inBlocks() { return new Options(threads, tileSize, progress, recordPixelRays, stop, true); }
    }

    /** Hears of finished tiles, from the worker threads (possibly out of order). */
    public interface TileListener {
        /**
         * Called when a tile is finished.
         *
         * @param done  the tiles finished so far
         * @param total the tiles in the image
         * @param image the image being filled in (read it, do not write it: the workbench shows it as it grows)
         */
        void tilesDone(int done, int total, Image image);
    }

    private Renderer() {
    }

    /**
     * {@return the rendered image and its statistics}, one pixel at a time by the recursive tracer
     *
     * @param scene the scene
     * @param queries makes one ray query (tree traversal) per thread
     * @param options threads, tiles and progress
     */
    public static RenderResult render(Scene scene, Supplier<? extends RayQuery> queries, Options options) {
        EffectPlan plan = new EffectPlan(scene);
        return render(scene, plan, () -> new Tracer(scene, plan, queries.get()), options);
    }

    /**
     * {@return the rendered image and its statistics}, with the structure's queries and packet
     * queries: in blocks of 8 x 8 pixels with their rays in packets where its packet loop traces
     * a packet's rays together and repays it ({@link PacketQuery#repaysBlocks}) or the options ask for
     * blocks ({@link Options#inBlocks}), else one pixel at a time;
     * the same image either way ({@link RenderResult#tracer} says which)
     *
     * @param scene     the scene
     * @param structure the structure built over the scene's mesh
     * @param options   threads, tiles and progress
     */
    public static RenderResult render(Scene scene, AccelerationStructure structure, Options options) {
        EffectPlan plan = new EffectPlan(scene);
        return render(scene, plan, () -> new Tracer(scene, plan, structure.query(), structure.packetQuery(), Tracer.SHADOW_BUDGET, options.blocks()), options);
    }

    private static RenderResult render(Scene scene, EffectPlan plan, Supplier<Tracer> tracers, Options options) {
        int w = scene.camera().width(), h = scene.camera().height(), ts = options.tileSize();
        int tilesX = (w + ts - 1) / ts, tilesY = (h + ts - 1) / ts, tiles = tilesX * tilesY;
        Image image = new Image(w, h);
        int[][] pixelRays = options.recordPixelRays() ? new int[RayKind.values().length][w * h] : null;
        TileListener progress = options.progress() != null ? options.progress() : (d, t, i) -> { };
        BooleanSupplier stop = options.stop() != null ? options.stop() : () -> false;
        AtomicInteger next = new AtomicInteger(), done = new AtomicInteger();
        TileOrder order = new TileOrder(tiles);
        int threads = Math.max(1, options.threads());
        ExecutorService pool = Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "render");
            t.setDaemon(true);
            return t;
        });
        long t0 = System.nanoTime();
        List<Future<Tracer>> workers = new ArrayList<>();
        try {
            for (int i = 0; i < threads; i++) {
                workers.add(pool.submit(() -> {
                    Tracer tracer = tracers.get();
                    for (int k; !stop.getAsBoolean() && (k = next.getAndIncrement()) < tiles; ) {
                        int tile = order.tile(k);
                        int x0 = (tile % tilesX) * ts, y0 = (tile / tilesX) * ts;
                        renderTile(tracer, image, pixelRays, x0, y0, Math.min(w, x0 + ts), Math.min(h, y0 + ts));
                        progress.tilesDone(done.incrementAndGet(), tiles, image);
                    }
                    return tracer;
                }));
            }
            RayCounts total = new RayCounts();
            for (Future<Tracer> f : workers) total.merge(f.get().counts());
            return new RenderResult(image, plan, total, System.nanoTime() - t0, threads, pixelRays, done.get() < tiles,
                    workers.get(0).get().describe());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("render interrupted", e);
        } catch (ExecutionException e) {
            if (e.getCause() instanceof RuntimeException re) throw re;
            throw new IllegalStateException(e.getCause());
        } finally {
            pool.shutdownNow();
        }
    }

    /** The edge of a block of pixels traced together (8 x 8: {@link org.kdtree.accel.RayPacket#CAPACITY} camera rays a packet). */
    private static final int PACKET = 8;

    private static void renderTile(Tracer tracer, Image image, int[][] pixelRays, int x0, int y0, int x1, int y1) {
        RayCounts c = tracer.counts();
        long[] before = new long[RayKind.values().length];
        double[] rgb = new double[3];
        if (tracer.tracesPackets()) {
            // Blocks of 8 x 8 pixels, their camera and shadow rays in packets; every pixel the same colour as alone.
            for (int by = y0; by < y1; by += PACKET)
                for (int bx = x0; bx < x1; bx += PACKET) {
                    int ex = Math.min(x1, bx + PACKET), ey = Math.min(y1, by + PACKET), i = 0;
                    tracer.block(bx, by, ex, ey);
                    for (int y = by; y < ey; y++)
                        for (int x = bx; x < ex; x++, i++) {
                            tracer.blockColour(i, rgb);
                            image.set(x, y, rgb[0], rgb[1], rgb[2]);
                            if (pixelRays != null)
                                for (RayKind k : RayKind.values()) pixelRays[k.ordinal()][y * image.width() + x] = tracer.blockRays(k, i);
                        }
                }
            return;
        }
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                if (pixelRays != null) for (RayKind k : RayKind.values()) before[k.ordinal()] = c.get(k);
                tracer.pixel(x, y, rgb);
                image.set(x, y, rgb[0], rgb[1], rgb[2]);
                if (pixelRays != null)
                    for (RayKind k : RayKind.values())
                        pixelRays[k.ordinal()][y * image.width() + x] = (int) (c.get(k) - before[k.ordinal()]);
            }
        }
    }
}
