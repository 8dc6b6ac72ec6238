package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import robosim.env.world.EndRule;
import robosim.env.world.RunRules;
import robosim.env.world.World;
import robosim.geometry.Pose2D;

/** A world's {@code open}, {@code <spawn>} and {@code <end>}, read and checked. */
class WorldRunRulesTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    private World world(String attributes, String children) {
        return fixtures.read("w.xml", """
                <world name="w" width="8000" height="6000"%s>
                  <wall x1="0" y1="3000" x2="2000" y2="3000"/>
                  %s
                </world>
                """.formatted(attributes, children));
    }

    /** Fails with the element on line 3, after a wall on line 2. */
    private void failsWith(String element, String... words) {
        fixtures.fails("w.xml", """
                <world name="w" width="8000" height="6000">
                  <wall x1="0" y1="3000" x2="2000" y2="3000"/>
                  %s
                </world>
                """.formatted(element), 3, words);
    }

    @Test
    void aWorldWithoutThemIsClosedWithoutSpawnsAndEndsAsBefore() {
        assertEquals(RunRules.DEFAULT, world("", "").rules());
    }

    @Test
    void anOpenWorldKeepsItsSpawnPosesInFileOrderWithHeadingsInRadians() {
        RunRules rules = world(" open=\"true\"", """
                <spawn x="1000" y="1000"/>
                  <spawn x="7000" y="5000" th="90"/>""").rules();

        assertEquals(true, rules.open());
        assertEquals(List.of(new Pose2D(1000, 1000, 0), new Pose2D(7000, 5000, Math.PI / 2)), rules.spawns());
    }

    @ParameterizedTest
    @CsvSource({"all-left, ALL_LEFT", "any-left, ANY_LEFT", "gold, GOLD"})
    void endWhenIsReadWithoutALimit(String word, EndRule.When when) {
        World w = world("", "<gold x=\"5000\" y=\"5000\" intensity=\"10\"/>\n  <end when=\"" + word + "\"/>");

        assertEquals(new EndRule(when, 0), w.rules().end());
    }

    @Test
    void endAfterStepsKeepsItsLimit() {
        assertEquals(new EndRule(EndRule.When.STEPS, 250), world("", "<end when=\"steps\" steps=\"250\"/>").rules().end());
    }

    @Test
    void anUnknownEndIsRefusedNamingTheKnownOnes() {
        failsWith("<end when=\"tired\"/>", "attribute when on <end> is 'tired'; it is one of all-left, any-left,"
                + " steps, gold");
    }

    @Test
    void endAfterStepsNeedsItsSteps() {
        failsWith("<end when=\"steps\"/>", "missing required attribute steps on <end when=\"steps\">");
    }

    @ParameterizedTest
    @CsvSource({"0", "-3", "2.5"})
    void stepsIsAWholeNumberOneOrGreater(String steps) {
        failsWith("<end when=\"steps\" steps=\"" + steps + "\"/>",
                "attribute steps on <end> is " + steps + " but must be a whole number, 1 or greater");
    }

    @Test
    void endWhenGoldNeedsGold() {
        failsWith("<end when=\"gold\"/>", "<end when=\"gold\"> in a world without <gold>");
    }

    @Test
    void aWorldHasOneEnd() {
        fixtures.fails("w.xml", """
                <world name="w" width="8000" height="6000">
                  <end when="all-left"/>
                  <end when="any-left"/>
                </world>
                """, 3, "a world has at most one <end>; the first is at line 2");
    }

    @Test
    void aSpawnPoseOutsideTheWorldIsRefused() {
        failsWith("<spawn x=\"9000\" y=\"100\"/>", "spawn pose at (9000, 100) is outside the world");
    }

    @Test
    void openIsTrueOrFalse() {
        fixtures.fails("w.xml", "<world name=\"w\" width=\"8000\" height=\"6000\" open=\"maybe\">\n</world>\n", 1,
                "attribute open on <world> is 'maybe' but must be true or false");
    }
}
