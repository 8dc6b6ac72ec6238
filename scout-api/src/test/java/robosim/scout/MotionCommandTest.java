package robosim.scout;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;

/** What each motion call sends, in RoboSim's units. */
class MotionCommandTest {
    private final ScriptedScout scout = new ScriptedScout();

    private Command only() {
        assertEquals(1, scout.sent.size(), scout.sent.toString());
        return scout.sent.remove(0);
    }

    @Test
    void vmSetsTheWheelVelocitiesRightThenLeft() {
        assertTrue(scout.vm(100, 50, 0));
        assertEquals(new Command.SetVel2(127, 254), only());
    }

    @Test
    void scoutVmWithoutSteeringDrivesBothWheelsAlike() {
        assertTrue(scout.scout_vm(100, 0));
        assertEquals(new Command.SetVel2(254, 254), only());
    }

    @Test
    void scoutVmSteersByTheRotationConstantTruncatedAsInC() {
        assertTrue(scout.scout_vm(0, 100)); // 100 · 0.118597 = 11.86, truncated to 11
        assertEquals(new Command.SetVel2(-11 * 2.54, 11 * 2.54), only());
        assertTrue(scout.scout_vm(50, -100));
        assertEquals(new Command.SetVel2(61 * 2.54, 39 * 2.54), only());
    }

    @Test
    void scoutVmTurnsAtTheRequestedRateOnTheScoutsWheelbase() {
        // 90 deg/s: the wheels differ by 2 · 900 · 0.118597 tenths of an inch per second
        double diffMm = 2 * 900 * Scout.ROTATION_CONSTANT * 2.54;
        double degPerS = Math.toDegrees(diffMm / 2 * 0.005794); // ARIA's rule with scout.p's DiffConvFactor
        assertEquals(90, degPerS, 0.1);
    }

    @Test
    void prMovesEachWheelByItsDistance() {
        assertTrue(scout.pr(1000, -1000, 0));
        assertEquals(new Command.MoveWheels(-2540, 2540), only());
    }

    @Test
    void acAndSpSetAccelerationsAndSpeeds() {
        assertTrue(scout.ac(100, 900, 0));
        assertEquals(new Command.SetAccel(254, 90), only());
        assertTrue(scout.sp(200, 450, 0));
        assertEquals(List.of(new Command.SetMaxTransVel(508), new Command.SetMaxRotVel(45)), scout.sent);
    }

    @Test
    void outOfRangeAccelerationsAndSpeedsAreRefused() {
        assertFalse(scout.ac(0, 100, 0));
        assertFalse(scout.ac(100, -1, 0));
        assertFalse(scout.sp(-1, 100, 0));
        assertEquals(List.of(), scout.sent);
    }

    @Test
    void stAndLpStop() {
        assertTrue(scout.st());
        assertTrue(scout.lp());
        assertEquals(List.of(new Command.Stop(), new Command.Stop()), scout.sent);
    }

    @Test
    void tkSays() {
        assertTrue(scout.tk("hello"));
        assertEquals(new Command.Say("hello"), only());
        assertFalse(scout.tk(null));
    }

    @Test
    void reportMetricAndEndRunSendTheirCommands() {
        assertTrue(scout.report_metric("cellsExplored", 14));
        assertTrue(scout.end_run("gold found"));
        assertEquals(List.of(new Command.ReportMetric("cellsExplored", 14), new Command.EndRun("gold found")),
                scout.sent);
    }

    @Test
    void aMetricOrAReasonThatBreaksItsRuleIsFalseAndSendsNothing() {
        assertFalse(scout.report_metric("cells explored", 1));
        assertFalse(scout.report_metric("cells", Double.POSITIVE_INFINITY));
        assertFalse(scout.end_run("line one\nline two"));
        assertFalse(scout.end_run(null));
        assertEquals(List.of(), scout.sent);
    }

    @Test
    void unsupportedCallsReturnFalseAndSendNothing() {
        assertFalse(scout.pa(10, 10, 0));
        assertFalse(scout.conf_ir(5, new int[] {0, 1, 255}));
        assertFalse(scout.conf_cp(1));
        assertEquals(List.of(), scout.sent);
    }

    @Test
    void everyCallReturnsFalseWhenNotConnected() {
        scout.disconnectNow();
        assertFalse(scout.vm(1, 1, 0));
        assertFalse(scout.scout_vm(1, 0));
        assertFalse(scout.pr(1, 1, 0));
        assertFalse(scout.ac(1, 1, 0));
        assertFalse(scout.sp(1, 1, 0));
        assertFalse(scout.st());
        assertFalse(scout.lp());
        assertFalse(scout.gs());
        assertFalse(scout.get_sn());
        assertFalse(scout.get_bp());
        assertFalse(scout.get_rc());
        assertFalse(scout.get_rv());
        assertFalse(scout.zr());
        assertFalse(scout.dp(0, 0));
        assertFalse(scout.da(0, 0));
        assertFalse(scout.ws(1, 1, 0, 1));
        assertFalse(scout.conf_tm(1));
        assertFalse(scout.conf_sn(1, new int[] {0}));
        assertFalse(scout.tk("x"));
        assertFalse(scout.report_metric("cells", 1));
        assertFalse(scout.end_run("done"));
        assertFalse(scout.disconnect_robot());
        assertEquals(List.of(), scout.sent);
    }

    @Test
    void aRealScoutThatNeverConnectedSaysWhyNot() {
        Scout s = new Scout("s1", "127.0.0.1", 1, ScriptedScout.scoutFile().toString());
        assertFalse(s.vm(1, 1, 0));
        assertEquals("scout", s.getParameters().subclass());
    }
}
