package robosim.env.world.xml;

import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Communications settings that break a rule of the format. */
class WorldCommsErrorTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    /** Fails with the element on line 3, after a wall on line 2. */
    private void failsWith(String element, String... words) {
        fixtures.fails("w.xml", """
                <world name="w" width="8000" height="8000">
                  <wall x1="0" y1="3000" x2="2000" y2="3000"/>
                  %s
                </world>
                """.formatted(element), 3, words);
    }

    @ParameterizedTest
    @CsvSource({"-1", "-0.5"})
    void rangeMustNotBeNegative(String range) {
        failsWith("<comms range=\"" + range + "\"/>",
                "attribute range on <comms> is " + range + " but must be 0 or greater");
    }

    @Test
    void rangeIsANumber() {
        failsWith("<comms range=\"far\"/>", "attribute range on <comms> is 'far', not a number");
    }

    @Test
    void wallsBlockIsTrueOrFalse() {
        failsWith("<comms wallsBlock=\"yes\"/>", "attribute wallsBlock on <comms> is 'yes' but must be true or false");
    }

    @ParameterizedTest
    @CsvSource({"0", "-1", "1.5"})
    void latencyIsAWholeNumberOneOrGreater(String latency) {
        failsWith("<comms latency=\"" + latency + "\"/>",
                "attribute latency on <comms> is " + latency + " but must be a whole number, 1 or greater");
    }

    @Test
    void latencyFitsInAnInt() {
        // no number in a world file is over 10^9, so an int always holds a whole one
        failsWith("<comms latency=\"3000000000\"/>",
                "attribute latency on <comms> is 3000000000 but must be from -1000000000 to 1000000000");
    }

    @ParameterizedTest
    @CsvSource({"-0.1", "1.5"})
    void lossIsFromZeroToOne(String loss) {
        failsWith("<comms loss=\"" + loss + "\"/>", "attribute loss on <comms> is " + loss + " but must be from 0 to 1");
    }

    @Test
    void lossIsANumber() {
        failsWith("<comms loss=\"5%\"/>", "attribute loss on <comms> is '5%', not a number");
    }

    @ParameterizedTest
    @CsvSource({"0", "-64", "100.5"})
    void maxBytesIsAWholeNumberOneOrGreater(String maxBytes) {
        failsWith("<comms maxBytes=\"" + maxBytes + "\"/>",
                "attribute maxBytes on <comms> is " + maxBytes + " but must be a whole number, 1 or greater");
    }

    @Test
    void atMostOneComms() {
        fixtures.fails("two.xml", """
                <world name="two" width="8000" height="8000">
                  <comms range="8000"/>
                  <wall x1="0" y1="3000" x2="2000" y2="3000"/>

                  <comms latency="2"/>
                </world>
                """, 5, "a world has at most one <comms>; the first is at line 2");
    }

    @Test
    void commsTakesOnlyItsAttributes() {
        failsWith("<comms range=\"8000\" bandwidth=\"10\"/>", "unknown attribute bandwidth on <comms>");
    }

    @Test
    void commsTakesNoChildElements() {
        failsWith("<comms><range>8000</range></comms>", "unknown element <range> in <comms>: range is an attribute");
    }
}
