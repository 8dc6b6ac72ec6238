package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.params.ConversionFactors;
import robosim.pioneer.LaserPacket;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.Sip;
import robosim.protocol.Bumpers;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;

/** A Pioneer server's status and laser packets, as literal bytes, become the robot's states in mm, mm/s and degrees. */
class SipToStateTest {
    /** A p3dx's factors as its parameter file gives them. */
    private static final ConversionFactors P3DX = new ConversionFactors(0.001534, 0.485, 1, 1, 0.0056, 20);

    /** A SIP's data: x, y, heading, wheels, stall/bump, flags, the sonar readings, then ROTVEL×10 among the optional fields. */
    private static Sip sip(int x, int y, int th, int left, int right, int stallBump, int flags, int[][] sonar,
                           int rotVelX10) {
        byte[] head = {(byte) x, (byte) (x >> 8), (byte) y, (byte) (y >> 8), (byte) th, (byte) (th >> 8),
                (byte) left, (byte) (left >> 8), (byte) right, (byte) (right >> 8), (byte) 130,
                (byte) stallBump, (byte) (stallBump >> 8), 0, 0, (byte) flags, (byte) (flags >> 8), 0,
                (byte) sonar.length};
        byte[] data = new byte[head.length + sonar.length * 3 + 10];
        System.arraycopy(head, 0, data, 0, head.length);
        int i = head.length;
        for (int[] r : sonar) {
            data[i++] = (byte) r[0];
            data[i++] = (byte) r[1];
            data[i++] = (byte) (r[1] >> 8);
        }
        // ANPORT (2), ANALOG, DIGIN, DIGOUT, BATTX10 (2), CHARGESTATE, then ROTVEL×10
        i += 8;
        data[i++] = (byte) rotVelX10;
        data[i] = (byte) (rotVelX10 >> 8);
        return Sip.decode(new PioneerPacket(0x33, data));
    }

    private static RobotState state(SipToState s, Sip sip) {
        return s.state(sip, 1, 100, List.of());
    }

    @Test
    void aSipIsReadInTheRobotsUnits() {
        RobotState st = state(new SipToState(P3DX, 16, 5000, false),
                sip(1000, 200, 1024, 100, 300, 0x0009, 0x1F, new int[][] {{0, 500}, {3, 1000}}, 573));
        assertEquals(485, st.x(), 1e-9, "1000 units × 0.485");
        assertEquals(97, st.y(), 1e-9);
        assertEquals(90.0, st.th(), 0.01, "1024 × 0.001534 rad");
        assertEquals(200, st.vel(), 1e-9, "(100 + 300) / 2");
        assertEquals(100, st.leftVel(), 1e-9);
        assertEquals(300, st.rightVel(), 1e-9);
        assertEquals(57.3, st.rotVel(), 1e-9, "ROTVEL × 10 = 573");
        assertTrue(st.stalled(), "bit 0: the left wheel stalled");
        assertEquals(1, st.collisions());
        assertEquals(1, st.get(Bumpers.PART).sectors(), "front bumper bit 3: the sector ahead");
        assertEquals(Boolean.TRUE, st.motorsEnabled(), "flags 0x1F: bit 0, the motors, is set");
        assertEquals(16, st.get(SonarReading.PART).ranges().length);
        assertEquals(500, st.get(SonarReading.PART).ranges()[0]);
        assertEquals(1000, st.get(SonarReading.PART).ranges()[3]);
        assertEquals(5000, st.get(SonarReading.PART).ranges()[1], "a sonar not yet read reads the maximum range");
    }

    @Test
    void thePositionFollowsThe15BitCountersAcrossTheirWrap() {
        SipToState s = new SipToState(P3DX, 0, 5000, false);
        state(s, sip(32760, 5, 0, 0, 0, 0, 0, new int[0][], 0));
        RobotState st = state(s, sip(10, 32766, 0, 0, 0, 0, 0, new int[0][], 0));
        assertEquals((32760 + 18) * 0.485, st.x(), 1e-6, "10 after 32760 is 18 units on");
        assertEquals((5 - 7) * 0.485, st.y(), 1e-6, "32766 after 5 is 7 units back");
    }

    @Test
    void aHeadingPast180DegreesIsNormalised() {
        RobotState st = state(new SipToState(P3DX, 0, 5000, false), sip(0, 0, 3000, 0, 0, 0, 0, new int[0][], 0));
        assertEquals(Math.toDegrees(3000 * 0.001534) - 360, st.th(), 1e-9);
    }

    @Test
    void withoutRotvelTheRotationComesFromTheWheelsAsAriaWorksItOut() {
        RobotState st = state(new SipToState(P3DX, 0, 5000, false), sip(0, 0, 0, -100, 100, 0, 0, new int[0][], 0));
        assertEquals(Math.toDegrees(100 * 0.0056), st.rotVel(), 1e-9);
    }

    @Test
    void sonarReadingsOfSeveralSipsMakeOneRingAndTheRingIsEmptyWhileTheSonarIsOff() {
        SipToState s = new SipToState(P3DX, 4, 5000, false);
        state(s, sip(0, 0, 0, 0, 0, 0, 0x1E, new int[][] {{0, 100}, {1, 200}}, 0));
        RobotState on = state(s, sip(0, 0, 0, 0, 0, 0, 0x1E, new int[][] {{2, 300}, {7, 900}}, 0));
        assertArrayEquals(new int[] {100, 200, 300, 5000}, on.get(SonarReading.PART).ranges(),
                "transducer 7 is not on a 4-ring");
        RobotState off = state(s, sip(0, 0, 0, 0, 0, 0, 0x01, new int[0][], 0));
        assertEquals(0, off.get(SonarReading.PART).ranges().length);
    }

    @Test
    void aStallCountsOneCollisionUntilItEnds() {
        SipToState s = new SipToState(P3DX, 0, 5000, false);
        state(s, sip(0, 0, 0, 0, 0, 0x0100, 0, new int[0][], 0));
        RobotState still = state(s, sip(0, 0, 0, 0, 0, 0x0101, 0, new int[0][], 0));
        state(s, sip(0, 0, 0, 0, 0, 0, 0, new int[0][], 0));
        RobotState again = state(s, sip(0, 0, 0, 0, 0, 0x0001, 0, new int[0][], 0));
        assertEquals(1, still.collisions());
        assertEquals(2, again.collisions());
        assertFalse(state(s, sip(0, 0, 0, 0, 0, 0, 0, new int[0][], 0)).stalled());
    }

    @Test
    void laserPacketsMakeAScanOnceTheLastPartHasCome() {
        SipToState s = new SipToState(P3DX, 0, 5000, false);
        // 0x61: total 4, first 0, 2 readings (range, reflectance, two spare bytes each), laser number, flags
        s.laser(LaserPacket.decode(new PioneerPacket(0x61, new byte[] {4, 0, 0, 0, 2,
                (byte) 0xE8, 0x03, 0, 0, 0, (byte) 0xD0, 0x07, 0, 0, 0, 0, 0})));
        assertEquals(0, state(s, sip(0, 0, 0, 0, 0, 0, 0, new int[0][], 0)).get(LaserReading.PART).ranges().length,
                "half a scan");
        s.laser(LaserPacket.decode(new PioneerPacket(0x61, new byte[] {4, 0, 2, 0, 2,
                (byte) 0xB8, 0x0B, 0, 0, 0, (byte) 0xA0, 0x0F, 0, 0, 0, 0, 0})));
        assertArrayEquals(new int[] {1000, 2000, 3000, 4000},
                state(s, sip(0, 0, 0, 0, 0, 0, 0, new int[0][], 0)).get(LaserReading.PART).ranges());
        s.laserOff();
        assertEquals(0, state(s, sip(0, 0, 0, 0, 0, 0, 0, new int[0][], 0)).get(LaserReading.PART).ranges().length);
    }
}
