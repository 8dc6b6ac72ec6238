package robosim.pioneer.server;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.pioneer.LaserPacket;

class LaserScanTest {
    private static int[] scan(double increment) {
        int n = (int) Math.round(180 / increment) + 1;
        int[] s = new int[n];
        for (int i = 0; i < n; i++) {
            s[i] = i;
        }
        return s;
    }

    @Test
    void aWholeScanGoesInPacketsOfThirtyTwo() {
        LaserScan l = new LaserScan();
        l.enable(1);
        List<LaserPacket> packets = l.packets(scan(1));
        assertEquals(6, packets.size());
        assertEquals(181, packets.get(0).total());
        assertEquals(32, packets.get(0).ranges().length);
        assertEquals(160, packets.get(5).first());
        assertEquals(21, packets.get(5).ranges().length);
    }

    @Test
    void aNarrowerFieldOfViewIsCutFromTheScan() {
        LaserScan l = new LaserScan();
        l.enable(2);
        assertNull(l.setStart(-10));
        assertNull(l.setEnd(10));
        assertNull(l.setResolution(2));
        List<LaserPacket> packets = l.packets(scan(1));
        assertEquals(1, packets.size());
        assertTrue(packets.get(0).extended());
        assertArrayEquals(new int[] {80, 82, 84, 86, 88, 90, 92, 94, 96, 98, 100}, packets.get(0).ranges());
    }

    @Test
    void halfDegreesAskTheEnvironmentForHalfDegrees() {
        LaserScan l = new LaserScan();
        l.enable(1);
        l.setResolution(0.5);
        assertEquals(0.5, l.baseIncrement());
        assertEquals(361, l.packets(scan(0.5)).get(0).total());
        assertEquals(0, l.packets(scan(1)).size(), "a scan of the old increment is not sent");
    }

    @Test
    void aWiderFieldOfViewIsNarrowedAndSaysSo() {
        LaserScan l = new LaserScan();
        assertEquals("the laser's field of view starts at -135.0°; it is cut to -90.0°", l.setStart(-135));
        assertEquals("the laser's resolution of 0.25° is taken as 0.5°", l.setResolution(0.25));
    }

    @Test
    void offMeansNoPackets() {
        assertEquals(0, new LaserScan().packets(scan(1)).size());
    }
}
