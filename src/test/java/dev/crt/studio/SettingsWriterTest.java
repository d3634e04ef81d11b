package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.scene.Settings;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Render → Settings… writing into the script: the edits, checked by compiling what they give. */
class SettingsWriterTest {
    private static final String SCENE = "Scene { Sphere { radius -> 1 } }\n";

    private static String apply(String script, Map<String, String> values) throws SettingsWriter.Refused {
        StringBuilder text = new StringBuilder(script);
        for (SettingsWriter.Edit e : SettingsWriter.edits(script, values)) text.replace(e.start(), e.end(), e.text());
        return text.toString();
    }

    private static Settings compiled(String script) {
        CompileResult r = CrtCompiler.compile(new Source("test.crt", script, null), CompileOptions.DEFAULT);
        assertThat(r.hasErrors()).as("%s compiles: %s", script, r.diagnostics()).isFalse();
        return r.scene().settings();
    }

    private static Map<String, String> values(String... pairs) {
        Map<String, String> m = new LinkedHashMap<>();
        for (int i = 0; i < pairs.length; i += 2) m.put(pairs[i], pairs[i + 1]);
        return m;
    }

    @Test
    void replacesTheLiteralsThatTakeEffectAndAddsTheMissingAttributesToTheLastBlock() throws Exception {
        String script = "-- a scene\nSettings {\n  width -> 320\n  height -> -0\n}\nSettings { width -> 640 }\n" + SCENE;
        String written = apply(script, values("width", "200", "height", "150", "gamma", "2.2"));
        assertThat(written).isEqualTo("-- a scene\nSettings {\n  width -> 320\n  height -> 150\n}\n"
                + "Settings { width -> 200 gamma -> 2.2 }\n" + SCENE);
        Settings s = compiled(written);
        assertThat(s.width()).isEqualTo(200);
        assertThat(s.height()).isEqualTo(150);
        assertThat(s.gamma()).isEqualTo(2.2);
    }

    @Test
    void aBlockWrittenOneAttributeALineGetsNewLinesWithItsIndentation() throws Exception {
        String script = "Settings {\n    width -> 32\n}\n" + SCENE;
        String written = apply(script, values("supersampling", "3", "recursiondepth", "2"));
        assertThat(written).isEqualTo("Settings {\n    width -> 32\n    supersampling -> 3\n    recursiondepth -> 2\n}\n" + SCENE);
        assertThat(compiled(written).supersampling()).isEqualTo(3);
        assertThat(compiled(written).recursionDepth()).isEqualTo(2);
    }

    @Test
    void aScriptWithoutSettingsGetsABlockAfterItsOpeningComments() throws Exception {
        String script = "-- only a sphere\n\n" + SCENE;
        String written = apply(script, values("width", "64", "dofsamples", "4"));
        assertThat(written).isEqualTo("-- only a sphere\n\nSettings { width -> 64 dofsamples -> 4 }\n" + SCENE);
        assertThat(compiled(written).dofSamples()).isEqualTo(4);
        assertThat(apply("", values("width", "64"))).isEqualTo("Settings { width -> 64 }\n");
    }

    @Test
    void aComputedValueIsRefusedWithItsPlaceAndNothingIsWritten() {
        String script = "w = 100\nSettings { width -> w * 2 height -> 50 }\n" + SCENE;
        assertThatThrownBy(() -> SettingsWriter.edits(script, values("height", "60", "width", "300")))
                .isInstanceOf(SettingsWriter.Refused.class)
                .hasMessage("width is computed by the expression 'w * 2' at 2:21, not written as a number: change it in the "
                        + "script, or apply the settings to this session only");
        String conditional = "Settings { width -> 10 }\nif (t > 2) { Settings { width -> 20 } }\n" + SCENE;
        assertThatThrownBy(() -> SettingsWriter.edits(conditional, values("width", "30")))
                .hasMessageStartingWith("width is set inside a block (an if, a while or a Scene) at 2:25");
        assertThatThrownBy(() -> SettingsWriter.edits("Settings { width -> }\n", values("width", "30")))
                .hasMessageStartingWith("the script has a syntax error at 1:");
    }

    @Test
    void offsetsCountJavaCharactersAlsoAfterCharactersBeyondTheBasicPlane() throws Exception {
        String script = "-- \uD83C\uDFA5 camera\nSettings { width -> 10 }\n" + SCENE;
        assertThat(apply(script, values("width", "12"))).isEqualTo("-- \uD83C\uDFA5 camera\nSettings { width -> 12 }\n" + SCENE);
    }
}
