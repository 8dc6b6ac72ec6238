package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A world's {@code motors} attribute: how a Pioneer's program finds the motors as it connects. */
class WorldMotorsTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    private boolean motorsEnabled(String attribute) {
        return fixtures.read("w.xml", "<world name=\"w\" width=\"8000\" height=\"6000\"" + attribute + ">\n</world>\n")
                .rules().motorsEnabled();
    }

    @Test
    void withoutTheAttributeTheMotorsAreDisabled() {
        assertFalse(motorsEnabled(""));
    }

    @Test
    void enabledAndDisabledAreRead() {
        assertTrue(motorsEnabled(" motors=\"enabled\""));
        assertFalse(motorsEnabled(" motors=\"disabled\""));
    }

    @Test
    void anyOtherValueIsRefusedNamingTheLineTheValueAndTheRule() {
        fixtures.fails("w.xml", "<world name=\"w\" width=\"8000\"\n  height=\"6000\" motors=\"on\">\n</world>\n", 1,
                "attribute motors on <world> is 'on' but must be enabled or disabled");
    }
}
