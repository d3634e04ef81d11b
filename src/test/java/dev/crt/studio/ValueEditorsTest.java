package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;

import java.beans.PropertyEditor;
import org.junit.jupiter.api.Test;

/** The property sheet's plain editors: the JDK's own, a fresh one per call, also after the first call registered them. */
class ValueEditorsTest {
    @Test
    void thePlainEditorsAreTheJdksOwnAndAFreshOnePerCall() {
        for (int call = 0; call < 2; call++) {
            PropertyEditor a = ValueEditors.plain(Double.class);
            PropertyEditor b = ValueEditors.plain(Double.class);
            assertThat(a).isNotNull().isNotSameAs(b);
            a.setAsText("2.5");
            b.setAsText("-1");
            assertThat(a.getValue()).isEqualTo(2.5);
            assertThat(b.getValue()).isEqualTo(-1.0);
            assertThat(ValueEditors.plain(Boolean.class).getTags()).containsExactly("True", "False");
            PropertyEditor text = ValueEditors.plain(String.class);
            text.setAsText("a \"quoted\" word");
            assertThat(text.getValue()).isEqualTo("a \"quoted\" word");
            PropertyEditor whole = ValueEditors.plain(Integer.class);
            whole.setAsText("42");
            assertThat(whole.getValue()).isEqualTo(42);
        }
    }

    @Test
    void aTypeWithoutAnEditorHasNone() {
        assertThat(ValueEditors.plain(ValueEditorsTest.class)).isNull();
    }
}
