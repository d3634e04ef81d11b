package dev.crt.lang.eval;

import dev.crt.lang.value.LightValue;
import dev.crt.lang.value.ListValue;
import dev.crt.lang.value.Value;
import dev.crt.scene.Background;
import dev.crt.scene.Camera;
import dev.crt.scene.Light;
import dev.crt.scene.Sampler;
import dev.crt.scene.Settings;
import dev.crt.scene.Shading;
import dev.crt.scene.SourceSpan;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/** The settings so far: every Settings block overrides the attributes it gives. */
final class SettingsState {
    static final Set<String> ATTRIBUTES = Settings.ATTRIBUTES;

    private Settings current = Settings.DEFAULT;
    /** The attributes the script's Settings blocks have given so far. */
    private final Set<String> given = new HashSet<>();
    private boolean hasCamera;
    private SourceSpan firstBlock;

    void apply(Attributes a) {
        if (firstBlock == null) firstBlock = a.typeSpan();
        Settings s = current;
        String title = a.string("title", s.title());
        String author = a.string("author", s.author());
        String date = a.string("date", s.date());
        String notes = a.string("notes", s.notes());
        List<Light> lights = a.has("lights") ? lights(a) : s.lights();
        Camera camera = a.has("camera") ? a.camera("camera") : s.camera();
        Background background = a.has("background") ? a.background("background") : s.background();
        int supersampling = a.integer("supersampling", s.supersampling(), 1, Settings.MAX_SUPERSAMPLING);
        int dofSamples = a.integer("dofsamples", s.dofSamples(), 1, Settings.MAX_DOF_SAMPLES);
        int recursionDepth = a.integer("recursiondepth", s.recursionDepth(), 0);
        double gamma = a.number("gamma", s.gamma(), Attributes.Range.POSITIVE);
        int width = a.integer("width", s.width(), 1);
        int height = a.integer("height", s.height(), 1);
        Sampler sampler = s.sampler();
        if (a.has("sampler")) {
            String word = a.string("sampler", sampler.word());
            Optional<Sampler> named = Sampler.of(word);
            if (named.isPresent()) {
                sampler = named.get();
            } else {
                a.error("sampler", "sampler must be " + Sampler.words() + ", got \"" + word + "\"");
            }
        }
        long seed = a.integer("seed", (int) s.seed(), 0);
        Shading shading = s.shading();
        if (a.has("shading")) {
            String word = a.string("shading", shading.word());
            Optional<Shading> named = Shading.of(word);
            if (named.isPresent()) {
                shading = named.get();
            } else {
                a.error("shading", "shading must be \"crt\" or \"original\", got \"" + word + "\"");
            }
        }
        given.addAll(a.names());
        a.finish();
        hasCamera |= a.has("camera");
        current = new Settings(title, author, date, notes, lights, camera, background, supersampling, dofSamples,
                recursionDepth, gamma, width, height, sampler, seed, s.noise(), shading, given);
    }

    private static List<Light> lights(Attributes a) {
        Value v = a.given("lights").value();
        if (v instanceof LightValue single) return List.of(single.light());
        if (!(v instanceof ListValue list)) {
            a.error("lights", "attribute 'lights' of Settings expects a list of lights, got " + v.typeName());
            return List.of();
        }
        List<Light> lights = new ArrayList<>();
        for (int i = 0; i < list.items().size(); i++) {
            if (list.items().get(i) instanceof LightValue light) {
                lights.add(light.light());
            } else {
                a.error("lights", "attribute 'lights' of Settings expects a list of lights, but item " + i + " is a "
                        + list.items().get(i).typeName());
                return List.of();
            }
        }
        return lights;
    }

    boolean hasCamera() { return hasCamera; }

    SourceSpan firstBlock() { return firstBlock; }

    Settings build() { return current; }
}
