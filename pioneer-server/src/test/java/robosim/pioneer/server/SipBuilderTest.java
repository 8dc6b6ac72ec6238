package robosim.pioneer.server;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.params.ConversionFactors;
import robosim.pioneer.Sip;
import robosim.protocol.RobotState;
import robosim.protocol.RobotStates;

class SipBuilderTest {
    static final ConversionFactors P3DX = new ConversionFactors(0.001534, 0.485, 1, 1, 0.0056, 20);

    private static RobotState state(double x, double y, double th, double left, double right, boolean stalled,
                                    int[] sonar, int bumpers) {
        return RobotStates.of(5, 500, x, y, th, (left + right) / 2, 12.5, left, right, stalled, sonar, 0, new int[0],
                null, List.of(), List.of(), bumpers);
    }

    @Test
    void positionsAreInTheRobotsFrameDividedByTheDistConvFactor() {
        OdometryFrame frame = new OdometryFrame();
        frame.resetAt(1000, 2000, 90);
        // 970 mm along the world's +y is 970 mm straight ahead of a robot that started facing +y
        Sip sip = new SipBuilder(P3DX).build(state(1000, 2970, 90, 100, 100, false, new int[0], 0), frame, true, false);
        assertEquals(2000, sip.xPos());
        assertEquals(0, sip.yPos());
        assertEquals(0, sip.th());
        assertEquals(100, sip.leftVel());
        assertEquals(125, sip.rotVelX10());
        assertEquals(Sip.FLAG_MOTORS, sip.flags());
    }

    @Test
    void theHeadingIsInUnitsOfTheAngleConvFactor() {
        Sip sip = new SipBuilder(P3DX).build(state(0, 0, 90, 0, 0, false, new int[0], 0), new OdometryFrame(), false,
                false);
        assertEquals(Math.round(Math.PI / 2 / 0.001534), sip.th());
    }

    @Test
    void aRingOfMoreThanSixteenSonarsTakesTwoSips() {
        int[] ring = new int[24];
        for (int i = 0; i < ring.length; i++) {
            ring[i] = 1000 + i;
        }
        SipBuilder b = new SipBuilder(new ConversionFactors(0.001534, 1, 1, 2, 0.0056, 20));
        Sip first = b.build(state(0, 0, 0, 0, 0, false, ring, 0), new OdometryFrame(), false, true);
        Sip second = b.build(state(0, 0, 0, 0, 0, false, ring, 0), new OdometryFrame(), false, true);
        Sip third = b.build(state(0, 0, 0, 0, 0, false, ring, 0), new OdometryFrame(), false, true);
        assertEquals(16, first.sonar().size());
        assertEquals(new Sip.SonarReading(0, 500), first.sonar().get(0), "ranges divided by the RangeConvFactor");
        assertEquals(8, second.sonar().size());
        assertEquals(16, second.sonar().get(0).index());
        assertEquals(0, third.sonar().get(0).index(), "and round again");
        assertEquals(Sip.FLAG_SONARS, first.flags());
    }

    @Test
    void noSonarReadingsWhileTheSonarIsOff() {
        Sip sip = new SipBuilder(P3DX).build(state(0, 0, 0, 0, 0, false, new int[] {5000}, 0), new OdometryFrame(),
                false, false);
        assertEquals(0, sip.sonar().size());
        assertEquals(0, sip.flags());
    }

    @Test
    void aStallSetsBothWheelsBitsAndBumpersTheirs() {
        Sip sip = new SipBuilder(P3DX).build(state(0, 0, 0, 0, 0, true, new int[0], 1), new OdometryFrame(), true,
                false);
        assertEquals(Sip.LEFT_STALL | Sip.RIGHT_STALL | 1 << 3, sip.stallBump(), "stall, and the front centre bumper");
    }

    @Test
    void aRobotStandingKeepsItsPoseAndSonarWithItsVelocitiesZero() {
        OdometryFrame frame = new OdometryFrame();
        frame.resetAt(1000, 2000, 90);
        Sip sip = new SipBuilder(P3DX).standing(state(1000, 2970, 90, 100, 120, false, new int[] {970}, 0), frame,
                true, true);
        assertEquals(2000, sip.xPos());
        assertEquals(0, sip.leftVel());
        assertEquals(0, sip.rightVel());
        assertEquals(0, sip.rotVelX10());
        assertEquals(false, sip.moving(), "a stopped SIP (0x32)");
        assertEquals(List.of(new Sip.SonarReading(0, 970)), sip.sonar());
    }
}
