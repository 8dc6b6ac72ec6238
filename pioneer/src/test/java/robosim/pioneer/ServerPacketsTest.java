package robosim.pioneer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;

class ServerPacketsTest {
    @Test
    void aSipComesBackFieldForField() {
        Sip sip = new Sip(true, 0x7ffe, 12, -2048, -300, 310, 130, Sip.LEFT_STALL | Sip.RIGHT_STALL | 0x02, 5,
                Sip.FLAG_MOTORS | Sip.FLAG_SONARS, 45,
                List.of(new Sip.SonarReading(0, 5000), new Sip.SonarReading(15, 250)),
                0xff, 0xff, 130, 0, -155, 0, 0, -127, 0);
        PioneerPacket p = sip.toPacket();
        assertEquals(Commands.SIP_MOVING, p.id());
        assertEquals(sip, Sip.decode(p));
    }

    @Test
    void aSipOfSixteenSonarsFitsAriasLimit() {
        List<Sip.SonarReading> sonar = new java.util.ArrayList<>();
        for (int i = 0; i < 16; i++) {
            sonar.add(new Sip.SonarReading(i, 5000));
        }
        Sip sip = new Sip(false, 0, 0, 0, 0, 0, 130, 0, 0, 0x1f, 0, sonar, 0xff, 0xff, 130, 0, 0, 0, 0, -127, 0);
        // MobileSim's p3dx SIP is 89 bytes on the wire
        assertEquals(89, sip.toPacket().encode().length);
    }

    @Test
    void theConfigReplyComesBackAndCarriesSim() {
        ConfigPacket c = new ConfigPacket("Pioneer", "p3dx", "SIM", 500, 2200, 300, 300, "r1", 100, false, true, true,
                2000, 500, 2200, 100, 100, 300, 300, 5, 5, "RoboSim 0.1");
        PioneerPacket p = c.toPacket();
        assertEquals(c, ConfigPacket.decode(p));
    }

    @Test
    void laserPacketsComeBackInBothForms() {
        LaserPacket plain = new LaserPacket(false, 1, 2, 3, 181, 32, new int[] {1000, 2000, 65535}, null);
        assertEquals(plain, LaserPacket.decode(plain.toPacket()));
        LaserPacket ext = new LaserPacket(true, 0, 0, 0, 3, 0, new int[] {10, 20, 30}, new int[] {0, 1, 2});
        LaserPacket back = LaserPacket.decode(ext.toPacket());
        assertArrayEquals(new int[] {10, 20, 30}, back.ranges());
        assertArrayEquals(new int[] {0, 1, 2}, back.reflectance());
    }

    @Test
    void aLaserPacketWhoseReadingsLieOutsideItsScanIsRefused() {
        LaserPacket bad = new LaserPacket(false, 0, 0, 0, 2, 1, new int[] {1, 2}, null);
        assertThrows(PacketFormatException.class, () -> LaserPacket.decode(bad.toPacket()));
    }

    @Test
    void simStatAndIdentityComeBack() {
        SimStat s = new SimStat(SimStat.ODOMETRY_ERROR, 100, 100, 101, -5000, 7000, 0, -90);
        assertEquals(s, SimStat.decode(s.toPacket()));
        RobotIdentity id = new RobotIdentity("r1", "Pioneer", "p3dx");
        assertEquals(id, RobotIdentity.decode(id.toPacket()));
    }
}
