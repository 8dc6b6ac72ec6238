package robosim.scout;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.scout.StateVector.*;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.RobotStates;

/** Where gs() puts each reading, and in which units. */
class StateVectorTest {
    private final ScriptedScout scout = new ScriptedScout();

    private static int[] sonar(int first, int rest) {
        int[] mm = new int[16];
        java.util.Arrays.fill(mm, rest);
        mm[0] = first;
        return mm;
    }

    @Test
    void theIndicesAreTheCLibrarys() {
        assertEquals(45, NUM_STATE);
        assertEquals(0, STATE_SIM_SPEED);
        assertEquals(1, STATE_IR_0);
        assertEquals(16, STATE_IR_15);
        assertEquals(17, STATE_SONAR_0);
        assertEquals(32, STATE_SONAR_15);
        assertEquals(33, STATE_BUMPER);
        assertEquals(34, STATE_CONF_X);
        assertEquals(35, STATE_CONF_Y);
        assertEquals(36, STATE_CONF_STEER);
        assertEquals(37, STATE_CONF_TURRET);
        assertEquals(38, STATE_VEL_TRANS);
        assertEquals(39, STATE_VEL_STEER);
        assertEquals(40, STATE_VEL_TURRET);
        assertEquals(41, STATE_MOTOR_STATUS);
        assertEquals(42, STATE_LASER);
        assertEquals(43, STATE_COMPASS);
        assertEquals(44, STATE_ERROR);
    }

    @Test
    void gsFillsEveryEntryInTheNomadsUnits() {
        scout.queue(ScriptedScout.at(1, 254, -508, -90, -127, 254, sonar(1000, 7000), 0b100001));
        assertTrue(scout.gs());
        long[] s = scout.State;
        assertEquals(100, s[STATE_CONF_X], "254 mm is 100 tenths of an inch");
        assertEquals(-200, s[STATE_CONF_Y]);
        assertEquals(2700, s[STATE_CONF_STEER], "-90 degrees is 270.0");
        assertEquals(2700, s[STATE_CONF_TURRET], "the Scout has no turret: the heading again");
        assertEquals(100, s[STATE_VEL_RIGHT], "the right wheel, 254 mm/s");
        assertEquals(-50, s[STATE_VEL_LEFT], "the left wheel, -127 mm/s");
        assertEquals(0, s[STATE_VEL_TURRET]);
        assertEquals(MOTOR_RIGHT | MOTOR_LEFT, s[STATE_MOTOR_STATUS]);
        assertEquals(39, s[STATE_SONAR_0], "1000 mm is 39 inches");
        assertEquals(255, s[STATE_SONAR_15], "7000 mm is beyond 255 inches");
        assertEquals(0b100001, s[STATE_BUMPER], "front and front-right sectors");
        for (int i = STATE_IR_0; i <= STATE_IR_15; i++) {
            assertEquals(0, s[i], "no infrared on a Scout");
        }
        assertEquals(0, s[STATE_LASER]);
        assertEquals(0, s[STATE_COMPASS]);
        assertEquals(0, s[STATE_ERROR]);
        assertTrue(s[STATE_SIM_SPEED] >= 0);
    }

    @Test
    void aStoppedWheelClearsItsMotorBit() {
        scout.queue(ScriptedScout.at(1, 0, 0, 0, 0, 100, new int[0], 0), ScriptedScout.at(2, 0, 0, 0, 100, 0, new int[0], 0),
                ScriptedScout.at(3, 0, 0, 0, 0, 0, new int[0], 0));
        scout.get_rv();
        assertEquals(MOTOR_RIGHT, scout.State[STATE_MOTOR_STATUS]);
        scout.get_rv();
        assertEquals(MOTOR_LEFT, scout.State[STATE_MOTOR_STATUS]);
        scout.get_rv();
        assertEquals(0, scout.State[STATE_MOTOR_STATUS]);
    }

    @Test
    void eachGetRefreshesOnlyItsPart() {
        scout.queue(ScriptedScout.at(1, 254, 0, 90, 0, 0, sonar(254, 254), 1),
                ScriptedScout.at(2, 508, 0, 90, 0, 0, sonar(508, 508), 2));
        assertTrue(scout.get_bp());
        assertEquals(1, scout.State[STATE_BUMPER]);
        assertEquals(0, scout.State[STATE_CONF_X], "get_bp leaves the configuration");
        assertEquals(255, scout.State[STATE_SONAR_0], "and the sonars");
        assertTrue(scout.get_rc());
        assertEquals(200, scout.State[STATE_CONF_X]);
        assertEquals(900, scout.State[STATE_CONF_STEER]);
        assertEquals(1, scout.State[STATE_BUMPER], "get_rc leaves the bumpers");
        assertEquals(255, scout.State[STATE_SONAR_0]);
        assertTrue(scout.get_sn());
        assertEquals(20, scout.State[STATE_SONAR_0]);
    }

    @Test
    void aRefusedRequestSetsTheErrorUntilTheNextGs() {
        scout.queue(RobotStates.of(1, 100, 0, 0, 0, 0, 0, 0, 0, false, new int[0], 0, new int[0], null, List.of(),
                List.of("no robot named r9"), 0));
        assertTrue(scout.gs());
        assertEquals(1, scout.State[STATE_ERROR]);
        assertTrue(scout.gs());
        assertEquals(0, scout.State[STATE_ERROR]);
    }

    @Test
    void sonarsReadTheMaximumUntilTheyFire() {
        for (int i = 0; i < 16; i++) {
            assertEquals(255, scout.State[STATE_SONAR_0 + i]);
        }
    }
}
