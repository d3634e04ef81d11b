package dev.crt.studio;

import dev.crt.animation.AnimationRun;
import dev.crt.animation.FramePattern;
import dev.crt.animation.FrameRange;
import dev.crt.animation.GifAssembly;
import dev.crt.image.FrameBuffer;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.Source;
import dev.crt.render.RenderStats;
import dev.crt.scene.Settings;
import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.io.File;
import java.io.IOException;
import java.lang.ref.SoftReference;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import javax.imageio.ImageIO;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JSlider;
import javax.swing.JSpinner;
import javax.swing.JToggleButton;
import javax.swing.SpinnerNumberModel;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * The Animation panel: renders a range of frames of the current script in the background with
 * {@code crt animate}'s engine ({@link AnimationRun}), scrubs and plays them, and exports them as
 * a GIF or a PNG sequence. A scrub position not rendered yet shows a coarse preview at once. The
 * scrub position is the studio's time t ({@link StudioModel#setTime}).
 */
final class AnimationPanel extends JPanel implements StudioModel.Listener {
    /** The preview of a frame not rendered yet traces every PREVIEW-th pixel each way, as the render view's coarse pass. */
    static final int PREVIEW = RenderJob.COARSE;

    private final StudioModel model;
    private final SessionSettings session;
    private final Throughput throughput;
    private final ConsolePanel console;

    private final JSpinner first = spinner("animFirst", "First frame", new SpinnerNumberModel(0, -1_000_000, 1_000_000, 1));
    private final JSpinner last = spinner("animLast", "Last frame", new SpinnerNumberModel(47, -1_000_000, 1_000_000, 1));
    private final JSpinner step = spinner("animStep", "Frame step", new SpinnerNumberModel(1, 1, 1_000_000, 1));
    private final JSpinner fps = spinner("animFps", "Frames per second", new SpinnerNumberModel(24.0, 1.0, 50.0, 1.0));
    private final JButton renderButton = new JButton("Render frames");
    private final JButton cancelButton = new JButton("Cancel");
    private final JProgressBar progress = new JProgressBar(0, 1000);
    private final JLabel status = new JLabel("Render frames (Shift+F5) renders the range");
    private final JSlider slider = new JSlider(0, 47, 0);
    private final JLabel timeLabel = new JLabel("t = 0");
    private final JToggleButton playButton = new JToggleButton("Play");
    private final JCheckBox loop = new JCheckBox("Loop", true);
    private final JButton exportGif = new JButton("Export GIF…");
    /** Whether an exported GIF loops forever (the NETSCAPE2.0 extension) or plays once. */
    private final JCheckBox gifLoop = new JCheckBox("Loop GIF", true);
    private final JButton exportPng = new JButton("Export PNGs…");
    private final FrameView view = new FrameView();
    private final Timer player;
    private final PreviewRenderer previews = new PreviewRenderer();

    /** The rendered frames by frame number, all made from the script text and settings of {@link #framesKey}. */
    private final Map<Integer, Rendered> frames = new TreeMap<>();
    private String framesKey;
    private String framesName = "animation";
    private Path cache;
    private Run run;
    private boolean adjusting;

    /** One rendered frame: its PNG in the cache folder, and its picture while memory allows. */
    private static final class Rendered {
        final Path file;
        SoftReference<BufferedImage> picture;

        Rendered(Path file, BufferedImage picture) {
            this.file = file;
            this.picture = new SoftReference<>(picture);
        }
    }

    /** A render of frames in progress. */
    private static final class Run {
        final AtomicBoolean cancel = new AtomicBoolean();
        final AtomicBoolean updatePending = new AtomicBoolean();
        final AtomicLong frameDone = new AtomicLong();
        final AtomicLong frameOf = new AtomicLong(1);
        int total;
        int finished;
        int written;
        Thread thread;
    }

    AnimationPanel(StudioModel model, SessionSettings session, Throughput throughput, ConsolePanel console) {
        super(new BorderLayout());
        this.model = model;
        this.session = session;
        this.throughput = throughput;
        this.console = console;
        getAccessibleContext().setAccessibleName("Animation");
        addHierarchyListener(e -> {
            if ((e.getChangeFlags() & java.awt.event.HierarchyEvent.SHOWING_CHANGED) != 0 && isShowing()) {
                currentChanged(model.current());
            }
        });

        JPanel range = new JPanel(new FlowLayout(FlowLayout.LEADING, 6, 2));
        range.add(new JLabel("Frames"));
        range.add(first);
        range.add(new JLabel("to"));
        range.add(last);
        range.add(new JLabel("step"));
        range.add(step);
        range.add(new JLabel("fps"));
        range.add(fps);
        named(renderButton, "animRender", "Render frames");
        named(cancelButton, "animCancel", "Cancel the frames");
        cancelButton.setEnabled(false);
        JPanel state = new JPanel(new BorderLayout(8, 0));
        state.setBorder(BorderFactory.createEmptyBorder(0, 6, 2, 6));
        progress.setName("animProgress");
        progress.setVisible(false);
        progress.setPreferredSize(new java.awt.Dimension(160, 14));
        status.setName("animStatus");
        JPanel actions = new JPanel(new FlowLayout(FlowLayout.LEADING, 6, 0));
        actions.add(renderButton);
        actions.add(cancelButton);
        actions.add(progress);
        state.add(actions, BorderLayout.LINE_START);
        state.add(status, BorderLayout.CENTER);
        JPanel top = new JPanel(new BorderLayout());
        top.add(range, BorderLayout.NORTH);
        top.add(state, BorderLayout.SOUTH);

        JPanel transport = new JPanel(new BorderLayout(6, 0));
        transport.setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.LEADING, 6, 0));
        named(playButton, "animPlay", "Play");
        named(loop, "animLoop", "Loop");
        named(exportGif, "animExportGif", "Export GIF");
        named(gifLoop, "animGifLoop", "Loop the exported GIF");
        gifLoop.setToolTipText("On: the GIF plays again and again; off: it plays once and stops on its last frame");
        named(exportPng, "animExportPng", "Export PNG sequence");
        buttons.add(playButton);
        buttons.add(loop);
        buttons.add(exportGif);
        buttons.add(gifLoop);
        buttons.add(exportPng);
        slider.setName("animSlider");
        slider.getAccessibleContext().setAccessibleName("Scrub frames");
        timeLabel.setName("animTime");
        JPanel scrub = new JPanel(new BorderLayout(6, 0));
        scrub.add(slider, BorderLayout.CENTER);
        scrub.add(timeLabel, BorderLayout.LINE_END);
        transport.add(scrub, BorderLayout.NORTH);
        transport.add(buttons, BorderLayout.SOUTH);

        add(top, BorderLayout.NORTH);
        add(view, BorderLayout.CENTER);
        add(transport, BorderLayout.SOUTH);

        player = new Timer(1000 / 24, e -> advance());
        renderButton.addActionListener(e -> renderFrames());
        cancelButton.addActionListener(e -> cancel());
        playButton.addActionListener(e -> setPlaying(playButton.isSelected()));
        exportGif.addActionListener(e -> exportGif());
        exportPng.addActionListener(e -> exportPngs());
        first.addChangeListener(e -> rangeChanged());
        last.addChangeListener(e -> rangeChanged());
        step.addChangeListener(e -> rangeChanged());
        fps.addChangeListener(e -> player.setDelay(delayMillis()));
        slider.addChangeListener(e -> {
            if (!adjusting) scrubbed();
        });
        rangeChanged();
    }

    private static JSpinner spinner(String name, String accessible, SpinnerNumberModel numbers) {
        JSpinner s = new JSpinner(numbers);
        // No grouping: a frame number reads 2000, as in crt animate --frames.
        s.setEditor(new JSpinner.NumberEditor(s, numbers.getValue() instanceof Double ? "0.##" : "#"));
        s.setName(name);
        s.getAccessibleContext().setAccessibleName(accessible);
        ((JSpinner.DefaultEditor) s.getEditor()).getTextField().setColumns(numbers.getValue() instanceof Double ? 2 : 4);
        ((JSpinner.DefaultEditor) s.getEditor()).getTextField().setName(name + "Text");
        return s;
    }

    private static void named(javax.swing.JComponent c, String name, String accessible) {
        c.setName(name);
        c.getAccessibleContext().setAccessibleName(accessible);
    }

    // ---------------------------------------------------------------- range and scrubbing

    /** The range the spinners give, or null (said in the status line) when the last frame comes before the first. */
    FrameRange range() {
        try {
            return new FrameRange((Integer) first.getValue(), (Integer) last.getValue(), (Integer) step.getValue());
        } catch (IllegalArgumentException e) {
            status.setText("Frames: " + e.getMessage());
            return null;
        }
    }

    private void rangeChanged() {
        FrameRange r = range();
        if (r == null) return;
        adjusting = true;
        try {
            int at = Math.min(slider.getValue(), r.size() - 1);
            slider.setMaximum(r.size() - 1);
            slider.setValue(at);
        } finally {
            adjusting = false;
        }
        scrubbed();
    }

    /** The frame number the slider is at. */
    int shownFrame() {
        FrameRange r = range();
        return r == null ? 0 : r.frame(Math.min(slider.getValue(), r.size() - 1));
    }

    private void scrubbed() {
        int frame = shownFrame();
        timeLabel.setText("t = " + frame);
        model.setTime(frame);
        show(frame);
    }

    /** Shows frame {@code frame}: its rendered picture, or else a coarse preview rendered now. */
    private void show(int frame) {
        BufferedImage picture = picture(frame);
        if (picture != null) {
            view.show(picture, false);
            return;
        }
        ScriptDocument d = model.current();
        if (d == null) return;
        previews.request(d.source(), frame, session, (image, error) -> {
            if (shownFrame() != frame || frames.containsKey(frame)) return;
            if (error != null) {
                status.setText("t = " + frame + ": " + error);
                return;
            }
            view.show(image, true);
        });
    }

    /** The rendered picture of {@code frame}, read back from its file if memory let it go; null when not rendered. */
    private BufferedImage picture(int frame) {
        Rendered r = frames.get(frame);
        if (r == null) return null;
        BufferedImage p = r.picture.get();
        if (p != null) return p;
        try {
            p = ImageIO.read(r.file.toFile());
        } catch (IOException e) {
            p = null;
        }
        if (p != null) r.picture = new SoftReference<>(p);
        return p;
    }

    private void setPlaying(boolean on) {
        playButton.setSelected(on);
        playButton.setText(on ? "Pause" : "Play");
        if (on) {
            player.setDelay(delayMillis());
            player.start();
        } else {
            player.stop();
        }
    }

    private int delayMillis() { return (int) Math.round(1000 / (Double) fps.getValue()); }

    /** One tick of play: the next rendered frame of the range, wrapping when looping. */
    private void advance() {
        FrameRange r = range();
        if (r == null || frames.isEmpty()) {
            setPlaying(false);
            return;
        }
        int at = slider.getValue();
        for (int k = 1; k <= r.size(); k++) {
            int index = at + k;
            if (index >= r.size()) {
                if (!loop.isSelected()) break;
                index -= r.size();
            }
            if (frames.containsKey(r.frame(index))) {
                slider.setValue(index);
                return;
            }
        }
        setPlaying(false);
    }

    // ---------------------------------------------------------------- rendering

    /** What the rendered frames were made from: the script and the session's settings. */
    private String key(ScriptDocument d) {
        return d.source().name() + "\u0000" + d.content() + "\u0000" + session.width + "," + session.height + ","
                + session.supersampling + "," + session.dofSamples + "," + session.recursionDepth + "," + session.gamma;
    }

    void renderFrames() {
        if (run != null) return;
        ScriptDocument d = model.current();
        FrameRange r = range();
        if (d == null || r == null) return;
        String key = key(d);
        if (!key.equals(framesKey)) {
            clearFrames();
            framesKey = key;
        }
        framesName = d.name().replaceFirst("\\.crt$", "");
        Path folder;
        try {
            folder = cacheFolder();
        } catch (IOException e) {
            failed("cannot make a folder for the frames: " + e.getMessage());
            return;
        }
        FramePattern pattern = FramePattern.parse(folder.resolve("frame_%d.png").toString());
        List<AnimationRun.Frame> todo = new ArrayList<>();
        for (int k = 0; k < r.size(); k++) {
            if (!frames.containsKey(r.frame(k))) todo.add(new AnimationRun.Frame(r.frame(k), pattern.path(r.frame(k))));
        }
        if (todo.isEmpty()) {
            status.setText("all " + r.size() + " frames of " + r + " are rendered");
            return;
        }
        Source source = d.source();
        Run job = new Run();
        job.total = todo.size();
        run = job;
        renderButton.setEnabled(false);
        cancelButton.setEnabled(true);
        progress.setValue(0);
        progress.setVisible(true);
        status.setText("rendering " + todo.size() + " frames…");
        long start = System.nanoTime();
        AnimationRun engine = new AnimationRun(source, CompileOptions.DEFAULT, session, 1, session.threadCount(), false,
                text -> SwingUtilities.invokeLater(() -> {
                    for (String line : text.split("\n")) {
                        console.log(line.contains(": error:") || line.startsWith("crt: frame") ? ConsolePanel.Kind.ERROR
                                : ConsolePanel.Kind.WARNING, line);
                    }
                }));
        AnimationRun.Listener listener = new AnimationRun.Listener() {
            @Override public void started(int frame) {
                job.frameDone.set(0);
                update(job);
            }

            @Override public void rendering(int frame, long done, long of) {
                job.frameDone.set(done);
                job.frameOf.set(Math.max(1, of));
                update(job);
            }

            @Override public void raysTraced(int frame, long rays) { throughput.add(rays, System.nanoTime()); }

            @Override public void written(AnimationRun.Frame frame, FrameBuffer image, Settings settings, RenderStats stats) {
                BufferedImage picture = picture(image, settings.outputGamma());
                SwingUtilities.invokeLater(() -> {
                    if (run != job) return;
                    job.written++;
                    frames.put(frame.number(), new Rendered(frame.file(), picture));
                    if (shownFrame() == frame.number()) view.show(picture, false);
                });
            }

            @Override public void finished(int frame, boolean written) {
                SwingUtilities.invokeLater(() -> {
                    job.finished++;
                    job.frameDone.set(0);
                    update(job);
                });
            }
        };
        job.thread = new Thread(() -> {
            AnimationRun.Outcome outcome;
            try {
                outcome = engine.run(todo, job.cancel::get, listener);
            } catch (RuntimeException | OutOfMemoryError e) {
                String message = e instanceof OutOfMemoryError ? "the frames need more memory than the Java heap has"
                        : "internal error while rendering frames: " + e;
                SwingUtilities.invokeLater(() -> ended(job, null, message, start));
                return;
            }
            SwingUtilities.invokeLater(() -> ended(job, outcome, null, start));
        }, "crt-studio-frames");
        job.thread.setDaemon(true);
        job.thread.start();
    }

    /** Progress to the EDT, one update waiting at a time (render threads report far more often than a repaint). */
    private void update(Run job) {
        if (!job.updatePending.compareAndSet(false, true)) return;
        SwingUtilities.invokeLater(() -> {
            job.updatePending.set(false);
            if (run != job) return;
            double part = (double) job.frameDone.get() / job.frameOf.get();
            progress.setValue((int) Math.min(1000, 1000 * (job.finished + Math.min(1, part)) / job.total));
            status.setText(String.format(Locale.ROOT, "rendering frame %d of %d…", Math.min(job.total, job.finished + 1), job.total));
        });
    }

    private void ended(Run job, AnimationRun.Outcome outcome, String error, long start) {
        if (run != job) return;
        run = null;
        renderButton.setEnabled(true);
        cancelButton.setEnabled(false);
        progress.setVisible(false);
        if (error != null) {
            failed(error);
            return;
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        if (outcome.cancelled()) {
            status.setText(String.format(Locale.ROOT, "cancelled: %d of %d frames rendered (kept)", job.written, job.total));
            console.log(ConsolePanel.Kind.INFO, "animation cancelled after " + job.written + " of " + job.total + " frames");
        } else if (!outcome.failures().isEmpty()) {
            AnimationRun.Failure f = outcome.failures().get(0);
            failed("frame " + f.frame() + " failed: " + f.reason());
        } else {
            String done = String.format(Locale.ROOT, "%d frames in %.1f s (%.1f frames/s)", job.written, seconds,
                    job.written / Math.max(1e-9, seconds));
            status.setText(done);
            console.log(ConsolePanel.Kind.INFO, "animation of " + framesName + ": " + done);
        }
        show(shownFrame());
    }

    private void failed(String message) {
        status.setText(message);
        console.log(ConsolePanel.Kind.ERROR, message);
    }

    /** Asks the frames being rendered to stop; the frames already written stay. */
    void cancel() {
        if (run == null) return;
        run.cancel.set(true);
        status.setText("cancelling…");
    }

    boolean isRendering() { return run != null; }

    /** A frame's picture as the PNG writer encodes it. */
    private static BufferedImage picture(FrameBuffer image, double gamma) {
        int w = image.width(), h = image.height();
        BufferedImage p = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] pixels = ((DataBufferInt) p.getRaster().getDataBuffer()).getData();
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) pixels[y * w + x] = RenderJob.rgb(image, x, y, gamma);
        }
        return p;
    }

    private Path cacheFolder() throws IOException {
        if (cache == null || !Files.isDirectory(cache)) cache = Files.createTempDirectory("crt-studio-frames-");
        return cache;
    }

    private void clearFrames() {
        for (Rendered r : frames.values()) {
            try {
                Files.deleteIfExists(r.file);
            } catch (IOException e) {
                // A stale frame left in the temporary folder goes with the folder when the studio quits.
            }
        }
        frames.clear();
    }

    // ---------------------------------------------------------------- export

    /** The rendered frames of the range, in order. */
    private List<Map.Entry<Integer, Path>> renderedInRange() {
        List<Map.Entry<Integer, Path>> out = new ArrayList<>();
        FrameRange r = range();
        if (r == null) return out;
        for (int k = 0; k < r.size(); k++) {
            Rendered f = frames.get(r.frame(k));
            if (f != null) out.add(Map.entry(r.frame(k), f.file));
        }
        return out;
    }

    private List<Map.Entry<Integer, Path>> framesToExport() {
        List<Map.Entry<Integer, Path>> list = renderedInRange();
        FrameRange r = range();
        if (list.isEmpty()) {
            JOptionPane.showMessageDialog(this, "No frame of the range is rendered yet: press Render frames first.",
                    "Nothing to export", JOptionPane.INFORMATION_MESSAGE);
            return null;
        }
        if (r != null && list.size() < r.size() && JOptionPane.showConfirmDialog(this, "Only " + list.size() + " of the "
                + r.size() + " frames are rendered. Export those?", "Export", JOptionPane.YES_NO_OPTION) != JOptionPane.YES_OPTION) {
            return null;
        }
        return list;
    }

    private void exportGif() {
        List<Map.Entry<Integer, Path>> list = framesToExport();
        if (list == null) return;
        JFileChooser chooser = new JFileChooser();
        chooser.setFileFilter(new FileNameExtensionFilter("Animated GIF (*.gif)", "gif"));
        chooser.setSelectedFile(new File(framesName + ".gif"));
        if (chooser.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) return;
        Path target = chooser.getSelectedFile().toPath();
        if (!target.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".gif")) {
            target = target.resolveSibling(target.getFileName() + ".gif");
        }
        if (!confirmReplace(List.of(target))) return;
        double rate = (Double) fps.getValue();
        List<Path> files = list.stream().map(Map.Entry::getValue).toList();
        Path gif = target;
        boolean loops = gifLoop.isSelected();
        exporting("writing " + gif.getFileName() + "…", () -> {
            GifAssembly.write(gif, files, rate, loops);
            return String.format(Locale.ROOT, "wrote %s (%d frames at %s fps, %s)", gif, files.size(), rate,
                    loops ? "looping" : "played once");
        });
    }

    private void exportPngs() {
        List<Map.Entry<Integer, Path>> list = framesToExport();
        if (list == null) return;
        JFileChooser chooser = new JFileChooser();
        chooser.setDialogTitle("Export PNGs: the name holds the frame number as %04d");
        chooser.setSelectedFile(new File(framesName + "_%04d.png"));
        if (chooser.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) return;
        String name = chooser.getSelectedFile().toString();
        if (!name.toLowerCase(Locale.ROOT).endsWith(".png")) name += ".png";
        FramePattern pattern;
        try {
            pattern = FramePattern.parse(name);
        } catch (IllegalArgumentException e) {
            // A plain name gets the frame number before its extension.
            pattern = FramePattern.parse(name.substring(0, name.length() - 4).replace("%", "%%") + "_%04d.png");
        }
        List<Path> targets = new ArrayList<>();
        for (Map.Entry<Integer, Path> f : list) targets.add(pattern.path(f.getKey()));
        if (!confirmReplace(targets)) return;
        exporting("writing " + targets.size() + " PNGs…", () -> {
            for (int i = 0; i < list.size(); i++) {
                Path target = targets.get(i);
                if (target.toAbsolutePath().getParent() != null) Files.createDirectories(target.toAbsolutePath().getParent());
                AtomicText.write(target, Files.readAllBytes(list.get(i).getValue()));
            }
            return "wrote " + targets.size() + " PNGs: " + targets.get(0) + (targets.size() > 1 ? " … " + targets.get(targets.size() - 1) : "");
        });
    }

    private boolean confirmReplace(List<Path> targets) {
        List<Path> there = targets.stream().filter(Files::exists).toList();
        if (there.isEmpty()) return true;
        return JOptionPane.showConfirmDialog(this, (there.size() == 1 ? there.get(0) + " exists" : there.size()
                + " of the files exist (" + there.get(0) + " …)") + ". Replace?", "Export", JOptionPane.YES_NO_OPTION)
                == JOptionPane.YES_OPTION;
    }

    /** Something an export does off the Event Dispatch Thread, returning what to say when it is done. */
    private interface Export {
        String run() throws IOException;
    }

    private void exporting(String what, Export body) {
        status.setText(what);
        exportGif.setEnabled(false);
        exportPng.setEnabled(false);
        Thread t = new Thread(() -> {
            String done;
            String error = null;
            try {
                done = body.run();
            } catch (IOException e) {
                done = null;
                error = "cannot export: " + (e.getMessage() == null ? e.toString() : e.getMessage());
            }
            String said = done, problem = error;
            SwingUtilities.invokeLater(() -> {
                exportGif.setEnabled(true);
                exportPng.setEnabled(true);
                if (problem != null) {
                    failed(problem);
                } else {
                    status.setText(said);
                    console.log(ConsolePanel.Kind.INFO, said);
                }
            });
        }, "crt-studio-export");
        t.setDaemon(true);
        t.start();
    }

    // ---------------------------------------------------------------- model events and life

    @Override
    public void currentChanged(ScriptDocument document) {
        // A preview is a compile and a render: none for a panel nobody sees (it sits behind the render
        // view at start, where it would compete with the window's first paint); it comes when shown.
        if (run == null && document != null && isShowing()) show(shownFrame());
    }

    /** Stops the render, the player and the previews, and deletes the frames' temporary folder. */
    void dispose() {
        cancel();
        player.stop();
        previews.shutdown();
        Thread t = run == null ? null : run.thread;
        if (t != null) {
            try {
                t.join(5000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        if (cache == null) return;
        try (DirectoryStream<Path> files = Files.newDirectoryStream(cache)) {
            for (Path f : files) Files.deleteIfExists(f);
            Files.deleteIfExists(cache);
        } catch (IOException e) {
            // The system's temporary folder is cleaned by the system in the end.
        }
    }

    // ---------------------------------------------------------------- for the tests

    /** The frame numbers rendered, in order. */
    List<Integer> renderedFrames() { return List.copyOf(frames.keySet()); }

    BufferedImage shownPicture() { return view.picture(); }

    boolean showsPreview() { return view.isPreview(); }

    Path cache() { return cache; }
}
