package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

class ShippedAssetsTest {
    @Test
    void theAssetsFolderBesideTheBuildIsSearched() {
        String before = System.clearProperty("crt.assets");
        try {
            Main.useShippedAssets();
            assertThat(System.getProperty("crt.assets")).isEqualTo(Path.of("assets").toAbsolutePath().toString());
            assertThat(Path.of(System.getProperty("crt.assets"), "sky.png")).exists();
        } finally {
            if (before == null) System.clearProperty("crt.assets");
            else System.setProperty("crt.assets", before);
        }
    }

    @Test
    void anExplicitFolderIsKept() {
        String before = System.setProperty("crt.assets", "/somewhere/else");
        try {
            Main.useShippedAssets();
            assertThat(System.getProperty("crt.assets")).isEqualTo("/somewhere/else");
        } finally {
            if (before == null) System.clearProperty("crt.assets");
            else System.setProperty("crt.assets", before);
        }
    }
}
