package robosim.env.world.xml;

import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** World properties that break a rule of the format. */
class WorldPropertyErrorTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    /** Fails with the element on line 3, after a property on line 2. */
    private void failsWith(String element, String... words) {
        fixtures.fails("w.xml", """
                <world name="w" width="8000" height="8000">
                  <property name="cellSize" value="1000"/>
                  %s
                </world>
                """.formatted(element), 3, words);
    }

    @Test
    void aNameIsGivenTwiceNamingTheFirstLine() {
        failsWith("<property name=\"cellSize\" value=\"2000\"/>",
                "property cellSize is given twice (value '2000'): a world gives each property once; "
                        + "the first is at line 2");
    }

    @Test
    void theNameIsRequired() {
        failsWith("<property value=\"1\"/>", "missing required attribute name on <property>");
    }

    @Test
    void theNameIsNotEmpty() {
        failsWith("<property name=\" \" value=\"1\"/>", "attribute name on <property> is empty");
    }

    @ParameterizedTest
    @ValueSource(strings = {"1cell", "_x", "cell size", "cell!", "é",
        "a1234567890123456789012345678901234567890123456789012345678901234"})
    void theNameFollowsTheRule(String name) {
        failsWith("<property name=\"" + name + "\" value=\"1\"/>", "attribute name on <property> is '",
                "but a property's name is a letter (A-Z, a-z) then up to 63 letters, digits, '.', '_' or '-'");
    }

    @Test
    void theValueIsRequired() {
        failsWith("<property name=\"goal\"/>", "missing required attribute value on <property> goal");
    }

    @Test
    void theValueIsAtMost1024Characters() {
        failsWith("<property name=\"goal\" value=\"" + "x".repeat(1025) + "\"/>",
                "attribute value on <property> goal is 1025 characters but must be at most 1024");
    }

    @Test
    void anUnknownAttributeIsRefused() {
        failsWith("<property name=\"goal\" value=\"1\" unit=\"mm\"/>", "unknown attribute unit on <property>");
    }

    @Test
    void aWorldHasAtMost256Properties() {
        StringBuilder text = new StringBuilder("<world name=\"w\" width=\"8000\" height=\"8000\">\n");
        for (int i = 1; i <= 257; i++) {
            text.append("  <property name=\"p").append(i).append("\" value=\"\"/>\n");
        }
        fixtures.fails("w.xml", text.append("</world>\n").toString(), 258,
                "a world has at most 256 <property> elements; this is one more");
    }
}
