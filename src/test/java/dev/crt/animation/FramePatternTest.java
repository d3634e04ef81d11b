package dev.crt.animation;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

class FramePatternTest {
    @Test
    void frameNumberReplacesTheConversion() {
        assertThat(FramePattern.parse("frames/f_%04d.png").path(7)).isEqualTo(Path.of("frames/f_0007.png"));
        assertThat(FramePattern.parse("f%d.ppm").path(123)).isEqualTo(Path.of("f123.ppm"));
        assertThat(FramePattern.parse("f%3d.ppm").path(5)).isEqualTo(Path.of("f005.ppm"));
        assertThat(FramePattern.parse("f_%04d.png").path(-3)).isEqualTo(Path.of("f_-003.png"));
    }

    @Test
    void frameNumberMayNameAFolderAndPercentSignsStayLiteral() {
        FramePattern p = FramePattern.parse("100%%/shot_%02d/beauty.png");
        assertThat(p.path(4)).isEqualTo(Path.of("100%/shot_04/beauty.png"));
        assertThat(p.extension()).isEqualTo("png");
    }

    @Test
    void patternWithoutTheFrameNumberIsRefused() {
        assertThatThrownBy(() -> FramePattern.parse("frame.png")).hasMessageContaining("needs the frame number");
        assertThatThrownBy(() -> FramePattern.parse("frame%%d.png")).hasMessageContaining("needs the frame number");
    }

    @Test
    void moreThanOneOrAnotherConversionIsRefused() {
        assertThatThrownBy(() -> FramePattern.parse("f%d_%d.png")).hasMessageContaining("more than one");
        assertThatThrownBy(() -> FramePattern.parse("f%s.png")).hasMessageContaining("unsupported conversion at '%s.png'");
        assertThatThrownBy(() -> FramePattern.parse("f%x.png")).hasMessageContaining("unsupported conversion");
        assertThatThrownBy(() -> FramePattern.parse("f%-4d.png")).hasMessageContaining("unsupported conversion");
        assertThatThrownBy(() -> FramePattern.parse("f%4")).hasMessageContaining("unsupported conversion");
    }
}
