package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The classes the studio loads ahead of the property sheet's first paint exist in the library it ships with. */
class LibraryClassesTest {
    @Test
    void everyClassNamedForPreloadingExists() {
        assertThat(LibraryClasses.count()).isPositive();
        assertThat(LibraryClasses.load(LibraryClasses.names())).isEqualTo(LibraryClasses.count());
    }

    @Test
    void aNameThatIsNoClassIsSkipped() {
        assertThat(LibraryClasses.load("org.openide.explorer.propertysheet.NoSuchClass", "java.lang.String")).isEqualTo(1);
    }
}
