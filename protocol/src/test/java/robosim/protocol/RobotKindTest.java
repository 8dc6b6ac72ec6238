package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** The robot kinds and their traits. */
class RobotKindTest {
    @Test
    void theKindsAreNamedAsWorldFilesAndHellosNameThem() {
        assertEquals(List.of("pioneer", "scout"), RobotKind.ids());
        assertEquals(Optional.of(RobotKind.SCOUT), RobotKind.of("Scout"));
        assertEquals(Optional.empty(), RobotKind.of("nomad200"));
        assertEquals(Optional.empty(), RobotKind.of(null));
    }

    @Test
    void aPioneerHasAMotorSwitchAndAScoutHasNone() {
        assertTrue(RobotKind.PIONEER.hasMotorSwitch());
        assertFalse(RobotKind.SCOUT.hasMotorSwitch());
    }

    @Test
    void aParameterFilesClassSaysItsKind() {
        assertEquals(RobotKind.SCOUT, RobotKind.ofRobotClass("Scout"));
        assertEquals(RobotKind.PIONEER, RobotKind.ofRobotClass("Pioneer"));
        assertEquals(RobotKind.PIONEER, RobotKind.ofRobotClass("PeopleBot"));
    }

    @Test
    void eachKindNamesItsApiAndDefaultParameters() {
        assertEquals("robosim.aria.ArRobot", RobotKind.PIONEER.apiClass());
        assertEquals("p3dx", RobotKind.PIONEER.defaultParameters());
        assertEquals("scout-api", RobotKind.SCOUT.apiModule());
        assertEquals("scout", RobotKind.SCOUT.defaultParameters());
    }
}
