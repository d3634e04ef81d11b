package dev.crt.render;

import dev.crt.image.FrameBuffer;
import dev.crt.scene.Entity;
import dev.crt.scene.Sampler;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.Shading;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Renders a Scene as docs/rendering.md defines it. {@link #prepare} builds the acceleration
 * structures once; {@link #render} may then run any number of times.
 */
public final class Renderer {
    /** Side of the square tiles handed out to threads (a multiple of {@link Candidates#BLOCK}). */
    static final int TILE = 32;
    /** Room for deep recursion (mirrors facing each other at a large recursiondepth); only reserved, not used. */
    private static final long RENDER_STACK = 256L << 20;

    private final Settings settings;
    private final List<Entity> entities;
    private final SceneGeometry geometry;
    private final Lights lights;
    private final BackgroundShader background;
    private final long buildNanos;
    /** Whether the picture goes to an output that clamps each channel at 1 ({@link #forClampedOutput}). */
    private final boolean clampedOutput;
    private volatile RenderStats stats;

    private Renderer(Scene scene) {
        long start = System.nanoTime();
        settings = scene.settings();
        entities = scene.entities();
        geometry = new SceneGeometry(scene.entities());
        lights = new Lights(settings.lights());
        Features.check(settings, geometry, lights);
        geometry.materials.prepare(settings.outputGamma());
        background = new BackgroundShader(settings.effectiveBackground(), settings.outputGamma(),
                settings.shading() == Shading.ORIGINAL);
        buildNanos = System.nanoTime() - start;
        clampedOutput = false;
        stats = new RenderStats(0, 0, 0, 0, buildNanos, 0);
    }

    /** {@code prepared} with other settings; {@code buildNanos} is the build time its stats report. */
    private Renderer(Renderer prepared, Settings settings, boolean clampedOutput, long buildNanos) {
        this.settings = settings;
        entities = prepared.entities;
        geometry = prepared.geometry;
        lights = prepared.lights;
        background = prepared.background;
        this.buildNanos = buildNanos;
        this.clampedOutput = clampedOutput;
        stats = new RenderStats(0, 0, 0, 0, buildNanos, 0);
    }

    /**
     * Builds what rendering {@code scene} needs (BVH and flattened primitive data).
     * @throws FeatureSwitchedOffException when the scene uses a feature this run leaves out (-Dcrt.without)
     */
    public static Renderer prepare(Scene scene) {
        return new Renderer(scene);
    }

    /**
     * This prepared scene at another image size and sampling, sharing the acceleration structure,
     * so that a quick preview pass costs no second build. Camera, lights and background stay.
     */
    public Renderer withImage(int width, int height, int supersampling, int dofSamples) {
        return new Renderer(this, settings.withSize(width, height).withSampling(supersampling, dofSamples), clampedOutput, 0);
    }

    /**
     * This prepared scene rendered for an output that clamps each channel to [0, 1] before it
     * stores it (8-bit PNG and PPM files, and the GIFs made of them): where every colour of the scene is
     * non-negative, a pixel's sum only grows as its rays add to it, so a pixel stops tracing once
     * the sum reaches 1 in every channel. The file is the same to the bit;
     * the image's values of 1 or more are then not the pixel's full colour, so PFM and any use of
     * the linear values need the plain renderer. Scenes with negative colours, textures, Gooch
     * shading, the 2015 model or the adaptive sampler render as without it.
     */
    public Renderer forClampedOutput() {
        return new Renderer(this, settings, true, buildNanos);
    }

    /** Whether pixels of this render stop at 1: see {@link #forClampedOutput}. */
    private boolean saturating() {
        return clampedOutput && settings.shading() != Shading.ORIGINAL && settings.effectiveSampler() != Sampler.ADAPTIVE
                && !geometry.materials.gooch() && geometry.materials.textures.isEmpty() && geometry.materials.nonNegative()
                && lights.nonNegative() && background.nonNegative();
    }

    /**
     * Renders the scene at its Settings' width and height on {@code threads} threads (0: all cores).
     * The result is bit-identical for any thread count.
     * @throws RenderCancelledException when the monitor cancels
     */
    public FrameBuffer render(int threads, RenderMonitor monitor) {
        long start = System.nanoTime();
        int width = settings.width(), height = settings.height();
        FrameBuffer image = new FrameBuffer(width, height);
        CameraRays camera = new CameraRays(settings.camera(), width, height);
        int tilesX = (width + TILE - 1) / TILE, tilesY = (height + TILE - 1) / TILE;
        int tiles = tilesX * tilesY;
        int workers = Math.max(1, Math.min(threads > 0 ? threads : Runtime.getRuntime().availableProcessors(), tiles));
        // The adaptive sampler renders twice: a pilot pass over every pixel, then, once every
        // pilot is in (a pixel's second pass reads its neighbours'), the pixels that need more.
        boolean adaptive = settings.effectiveSampler() == Sampler.ADAPTIVE;
        int passes = adaptive ? 2 : 1;
        float[] pilotVariance = adaptive ? new float[width * height] : null;
        CountDownLatch pilots = new CountDownLatch(adaptive ? tiles : 0);
        AtomicInteger nextTask = new AtomicInteger();
        int stride = tileStride(tiles);
        AtomicLong donePixels = new AtomicLong();
        AtomicBoolean cancelled = new AtomicBoolean();
        long total = (long) width * height * passes;
        List<Tracer> tracers = new ArrayList<>();
        List<Runnable> pool = new ArrayList<>();
        boolean saturating = saturating();
        // Tells the monitor the counted work begins now, before the first tile is done.
        monitor.progress(0, total);
        for (int w = 0; w < workers; w++) {
            Tracer tracer = new Tracer(geometry, lights, background);
            tracer.saturating = saturating;
            tracers.add(tracer);
            OriginalShading original = settings.shading() == Shading.ORIGINAL
                    ? new OriginalShading(tracer, geometry, lights, background) : null;
            PixelSampler sampler = new PixelSampler(tracer, original, camera, settings, pilotVariance,
                    () -> cancelled.get() || monitor.isCancelled());
            int block = sampler.blocks() ? Candidates.BLOCK : TILE;
            Runnable work = () -> {
                double[] rgb = new double[3];
                float[] pilot = new float[3];
                long reported = 0;
                int task;
                while (!cancelled.get() && (task = nextTask.getAndIncrement()) < tiles * passes) {
                    boolean second = task >= tiles;
                    if (second && !awaitPilots(pilots, cancelled, monitor)) return;
                    int tile = (int) ((long) (task % tiles) * stride % tiles);
                    int x0 = (tile % tilesX) * TILE, y0 = (tile / tilesX) * TILE;
                    int x1 = Math.min(x0 + TILE, width), y1 = Math.min(y0 + TILE, height);
                    // Checked at every pixel (and inside it, by the sampler): a pixel of thousands of
                    // samples is the longest a cancel waits, not a row of a tile.
                    // Block by block when camera rays share their block's list of candidates, else
                    // row by row as before (the 2015 model and the 360° projections take no list).
                    for (int by = y0; by < y1; by += block) {
                        for (int bx = x0; bx < x1; bx += block) {
                            for (int y = by, ye = Math.min(by + block, y1); y < ye; y++) {
                                for (int x = bx, xe = Math.min(bx + block, x1); x < xe; x++) {
                                    if (cancelled.get() || monitor.isCancelled()) {
                                        cancelled.set(true);
                                        return;
                                    }
                                    if (second) {
                                        for (int c = 0; c < 3; c++) pilot[c] = image.get(x, y, c);
                                        if (!sampler.refine(x, y, pilot, rgb)) continue;
                                    } else {
                                        sampler.pixel(x, y, rgb);
                                    }
                                    image.set(x, y, rgb[0], rgb[1], rgb[2]);
                                }
                            }
                        }
                    }
                    if (adaptive && !second) pilots.countDown();
                    long traced = tracer.primaryRays + tracer.shadowRays + tracer.reflectedRays + tracer.refractedRays;
                    monitor.raysTraced(traced - reported);
                    reported = traced;
                    monitor.tileDone(image, x0, y0, x1, y1);
                    monitor.progress(donePixels.addAndGet((long) (x1 - x0) * (y1 - y0)), total);
                }
            };
            pool.add(work);
        }
        runOnThreads(pool, "crt-render-", cancelled);
        if (geometry.materials.gooch() && !cancelled.get()) outlines(image, camera);
        long primary = 0, shadow = 0, reflected = 0, refracted = 0;
        for (Tracer t : tracers) {
            primary += t.primaryRays;
            shadow += t.shadowRays;
            reflected += t.reflectedRays;
            refracted += t.refractedRays;
        }
        stats = new RenderStats(primary, shadow, reflected, refracted, buildNanos, System.nanoTime() - start);
        if (cancelled.get()) throw new RenderCancelledException();
        return image;
    }

    /** Waits for every pilot tile; false when the render is cancelled meanwhile. */
    private static boolean awaitPilots(CountDownLatch pilots, AtomicBoolean cancelled, RenderMonitor monitor) {
        while (true) {
            if (cancelled.get() || monitor.isCancelled()) {
                cancelled.set(true);
                return false;
            }
            try {
                if (pilots.await(20, TimeUnit.MILLISECONDS)) return true;
            } catch (InterruptedException e) {
                cancelled.set(true);
                Thread.currentThread().interrupt();
                return false;
            }
        }
    }

    /**
     * A step coprime with the tile count, near the golden section of it: visiting tiles k·stride mod
     * tiles spreads the first tiles over the whole image, so the JIT profiles representative work
     * (not a band of empty sky) and the progress shown is an even preview. Pixels do not depend on it.
     */
    static int tileStride(int tiles) {
        int s = Math.max(1, (int) Math.round(tiles * 0.6180339887));
        while (gcd(s, tiles) != 1) s++;
        return s;
    }

    private static int gcd(int a, int b) {
        return b == 0 ? a : gcd(b, a % b);
    }

    /**
     * The entity seen through the centre of pixel (x, y) of the Settings' width × height, by the
     * pinhole ray (the lens is ignored), or empty where the background shows. Safe to call from
     * any thread, also while a render runs.
     */
    public Optional<Pick> pick(int x, int y) {
        int width = settings.width(), height = settings.height();
        if (x < 0 || y < 0 || x >= width || y >= height) return Optional.empty();
        Tracer tracer = new Tracer(geometry, lights, background);
        CameraRays camera = new CameraRays(settings.camera(), width, height);
        double[] d = new double[3];
        camera.direction(x, y, 0.5, 0.5, d);
        if (!tracer.closestHit(camera.px, camera.py, camera.pz, d[0], d[1], d[2], Double.POSITIVE_INFINITY)) {
            return Optional.empty();
        }
        int index = geometry.owner[tracer.hit.shape];
        return Optional.of(new Pick(index, entities.get(index), tracer.hit.t));
    }

    /**
     * The id pass: per pixel (row by row from the top), the index in the scene's entity list of the
     * entity seen through the pixel's centre, or −1 for the background. See {@link #pick}.
     */
    public int[] idPass() {
        int[] ids = new int[settings.width() * settings.height()];
        primaryHits((i, tracer) -> ids[i] = tracer == null ? -1 : geometry.owner[tracer.hit.shape]);
        return ids;
    }

    /**
     * The depth pass: per pixel (row by row from the top), the distance from the camera to the
     * surface seen through the pixel's centre, or +∞ for the background. See {@link #pick}.
     */
    public double[] depthPass() {
        double[] depth = new double[settings.width() * settings.height()];
        primaryHits((i, tracer) -> depth[i] = tracer == null ? Double.POSITIVE_INFINITY : tracer.hit.t);
        return depth;
    }

    /** Draws the Gooch materials' outlines over {@code image} from the primary hits through the pixel centres. */
    private void outlines(FrameBuffer image, CameraRays camera) {
        int n = settings.width() * settings.height();
        int[] shape = new int[n], face = new int[n];
        double[] t = new double[n];
        boolean[] flip = new boolean[n];
        primaryHits((i, tracer) -> {
            shape[i] = tracer == null ? -1 : tracer.hit.shape;
            if (tracer != null) {
                face[i] = tracer.hit.face;
                t[i] = tracer.hit.t;
                flip[i] = tracer.hit.flip;
            }
        });
        Outlines.draw(image, geometry, camera, shape, face, t, flip);
    }

    /** Receives pixel {@code i}'s primary hit, in {@code tracer.hit}, or null for the background. */
    private interface HitSink {
        void accept(int i, Tracer tracer);
    }

    /** Casts the pinhole ray through every pixel centre, on all cores, rows handed out in turn. */
    private void primaryHits(HitSink sink) {
        int width = settings.width(), height = settings.height();
        CameraRays camera = new CameraRays(settings.camera(), width, height);
        AtomicInteger nextRow = new AtomicInteger();
        AtomicBoolean stop = new AtomicBoolean();
        int workers = Math.max(1, Math.min(Runtime.getRuntime().availableProcessors(), height));
        List<Runnable> pool = new ArrayList<>();
        for (int w = 0; w < workers; w++) {
            Tracer tracer = new Tracer(geometry, lights, background);
            pool.add(() -> {
                double[] d = new double[3];
                int y;
                while (!stop.get() && (y = nextRow.getAndIncrement()) < height) {
                    for (int x = 0; x < width; x++) {
                        camera.direction(x, y, 0.5, 0.5, d);
                        boolean hit = tracer.closestHit(camera.px, camera.py, camera.pz, d[0], d[1], d[2],
                                Double.POSITIVE_INFINITY);
                        sink.accept(y * width + x, hit ? tracer : null);
                    }
                }
            });
        }
        runOnThreads(pool, "crt-pass-", stop);
    }

    /**
     * Runs each task on a thread of its own (with the render's large stack) and waits for all of
     * them. A task that fails, or an interrupt of the waiting thread, sets {@code stop} so the
     * others can end early; the first failure is rethrown once every thread has ended, and the
     * interrupt is kept.
     */
    private static void runOnThreads(List<Runnable> tasks, String name, AtomicBoolean stop) {
        Throwable[] failure = new Throwable[1];
        List<Thread> threads = new ArrayList<>();
        for (int i = 0; i < tasks.size(); i++) {
            Runnable task = tasks.get(i);
            Thread t = new Thread(null, () -> {
                try {
                    task.run();
                } catch (Throwable e) {
                    stop.set(true);
                    synchronized (failure) {
                        if (failure[0] == null) failure[0] = e;
                    }
                }
            }, name + i, RENDER_STACK);
            t.setDaemon(true);
            threads.add(t);
        }
        threads.forEach(Thread::start);
        boolean interrupted = false;
        for (Thread t : threads) {
            while (true) {
                try {
                    t.join();
                    break;
                } catch (InterruptedException e) {
                    interrupted = true;
                    stop.set(true);
                }
            }
        }
        if (interrupted) Thread.currentThread().interrupt();
        if (failure[0] instanceof RuntimeException e) throw e;
        if (failure[0] instanceof Error e) throw e;
    }

    /** Counts and timings of the last render (and of {@link #prepare}). */
    public RenderStats stats() {
        return stats;
    }

    /** The shape of the prepared acceleration structure, for statistics and benchmarks. */
    public SceneStructure structure() {
        Bvh bvh = geometry.bvh;
        return new SceneStructure(geometry.items.length, geometry.unbounded.length, geometry.shapes.count(),
                bvh == null ? 0 : bvh.nodeCount, bvh == null ? 0 : bvh.depth);
    }
}
