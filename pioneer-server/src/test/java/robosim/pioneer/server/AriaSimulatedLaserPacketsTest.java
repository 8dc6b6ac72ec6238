package robosim.pioneer.server;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.pioneer.Commands;
import robosim.pioneer.LaserPacket;
import robosim.pioneer.PioneerPacket;
import robosim.protocol.Command;
import robosim.protocol.RobotParameters;

/**
 * The laser's packets as ARIA's simulated laser configures and reads them (ArSimulatedLaser.cpp:
 * {@code internalConnect} sends 36 −90, 37 90, 38 100, 35 2; {@code simPacketHandler} reads 0x61
 * packets byte by byte and puts reading k of a scan at the laser's start angle + k × its increment).
 * C++ laserConnect over the port prints "32 m" as its closest reading although these readings are
 * right: the figure is ARIA's own (an LMS2xx chooses its field of view, so its getStartDegrees and
 * getEndDegrees stay 0, and currentReadingPolar(0, 0) matches no reading and answers the maximum
 * range), whatever the server. This pins the bytes that show the packets are not the cause.
 */
class AriaSimulatedLaserPacketsTest {
    private static final RobotParameters P3DX = new RobotParameters("Pioneer", "p3dx", 250, 425, 210, 301, 2200, 500,
            300, 300, 100, 100, 0.0056, 5000, List.of());

    /** The room of the comparison: the wall 2900 mm to the right, 6882 mm ahead of the laser. */
    private static int[] scan() {
        int[] s = new int[181];
        for (int k = 0; k <= 180; k++) {
            double th = Math.toRadians(k - 90);
            double right = th < 0 ? 2900 / Math.sin(-th) : Double.MAX_VALUE;
            double ahead = Math.cos(th) > 1e-9 ? 6882 / Math.cos(th) : Double.MAX_VALUE;
            s[k] = (int) Math.round(Math.min(Math.min(right, ahead), 8000));
        }
        return s;
    }

    @Test
    void ariasOldCommandsGiveExtendedPacketsWhoseFirstReadingIsTheRightHandWall() {
        LaserScan laser = new LaserScan();
        List<Command> requests = new ArrayList<>();
        CommandHandler h = new CommandHandler("r1", P3DX, SipBuilderTest.P3DX, laser, new OdometryFrame(),
                new RecordingEffects(requests, new ArrayList<>()));
        h.handle(Commands.comInt(36, -90));
        h.handle(Commands.comInt(37, 90));
        h.handle(Commands.comInt(38, 100));
        h.handle(Commands.comInt(35, 2));
        assertEquals(new Command.ConfigureLaser(true, 1, 8000), requests.get(requests.size() - 1));

        List<LaserPacket> packets = laser.packets(scan());
        assertEquals(6, packets.size());
        int[] read = new int[181];
        for (LaserPacket lp : packets) {
            PioneerPacket p = lp.toPacket();
            byte[] d = p.data();
            assertEquals(0x61, p.id(), "extended: no x, y, th before the counts");
            // simPacketHandler: total (2 bytes), readingNumber (2), newReadings (1), then per reading
            // range (2), reflectance (1) and two bytes it skips
            int total = u16(d, 0);
            int first = u16(d, 2);
            int n = d[4] & 0xff;
            assertEquals(181, total);
            for (int i = 0; i < n; i++) {
                read[first + i] = u16(d, 5 + 5 * i);
            }
        }
        // reading k at −90° + k: the right-hand wall first, straight ahead in the middle, the left last
        assertEquals(2900, read[0]);
        assertEquals(6882, read[90]);
        assertEquals(8000, read[180]);
        assertEquals(3349, read[30], "the wall on the right, 60° off the heading: 2900 / sin 60°");
    }

    private static int u16(byte[] d, int at) {
        return (d[at] & 0xff) | (d[at + 1] & 0xff) << 8;
    }
}
