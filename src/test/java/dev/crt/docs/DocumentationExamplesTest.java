package dev.crt.docs;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.DiagnosticFormatter;
import dev.crt.lang.Source;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/** Every ```crt example in the user documentation compiles without errors. */
class DocumentationExamplesTest {
    record Example(Path doc, int line, String text) {}

    static List<Example> examples(Path doc) throws IOException {
        List<String> lines = Files.readAllLines(doc);
        List<Example> found = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).strip().equals("```crt")) {
                int start = i + 1;
                int end = start;
                while (!lines.get(end).strip().equals("```")) end++;
                found.add(new Example(doc, start + 1, String.join("\n", lines.subList(start, end)) + "\n"));
                i = end;
            }
        }
        return found;
    }

    @TestFactory
    List<DynamicTest> everyExampleCompiles() throws IOException {
        List<DynamicTest> tests = new ArrayList<>();
        for (String name : List.of("language.md", "animation.md", "rendering.md")) {
            Path doc = Path.of("docs", name);
            if (!Files.exists(doc)) continue;
            for (Example e : examples(doc)) {
                tests.add(DynamicTest.dynamicTest(name + ":" + e.line(), () -> {
                    // The shipped assets, as the crt launcher finds them.
                    CompileResult r = CrtCompiler.compile(Source.of(name, e.text()), new CompileOptions(0,
                            List.of(Path.of("assets")), CompileOptions.DEFAULT_LOOP_BUDGET, CompileOptions.DEFAULT_TIME_BUDGET));
                    assertThat(r.hasErrors()).as(() -> r.diagnostics().stream()
                            .map(d -> DiagnosticFormatter.format(d, e.text())).collect(Collectors.joining("\n"))).isFalse();
                }));
            }
        }
        assertThat(tests).hasSizeGreaterThan(10);
        return tests;
    }
}
