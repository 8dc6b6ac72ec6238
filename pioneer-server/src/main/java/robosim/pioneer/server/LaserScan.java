package robosim.pioneer.server;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import robosim.pioneer.LaserPacket;
import robosim.protocol.Command;

/**
 * The simulated laser as an ARIA client configures it: on or off, plain ({@code 0x60}) or extended
 * ({@code 0x61}) packets, the field of view and the resolution. The Environment's laser scans
 * −90° to +90° at 1° or 0.5°; a field of view within that is cut from the scan, and a resolution
 * that is a whole multiple of 1° (or of 0.5°) takes every n-th reading. A field of view wider
 * than ±90° is narrowed to it, and a resolution finer than 0.5° becomes 0.5°; each is logged by the
 * session once. Set by the client's thread and read by the robot's: its methods hold its lock.
 */
final class LaserScan {
    private boolean on;
    private boolean extended;
    private double start = -90;
    private double end = 90;
    private double resolution = 1;

    /**
     * Starts or stops the laser.
     *
     * @param mode 0 off, 1 plain packets, 2 extended packets
     */
    synchronized void enable(int mode) {
        on = mode != 0;
        extended = mode == 2;
    }

    /** @return whether the laser is on */
    synchronized boolean isOn() {
        return on;
    }

    /**
     * @param degrees the first reading's angle from the laser's heading
     * @return null, or what was changed to fit the Environment's laser
     */
    synchronized String setStart(double degrees) {
        start = Math.max(-90, Math.min(90, degrees));
        return start == degrees ? null : "the laser's field of view starts at " + degrees + "°; it is cut to " + start + "°";
    }

    /**
     * @param degrees the last reading's angle from the laser's heading
     * @return null, or what was changed to fit the Environment's laser
     */
    synchronized String setEnd(double degrees) {
        end = Math.max(-90, Math.min(90, degrees));
        return end == degrees ? null : "the laser's field of view ends at " + degrees + "°; it is cut to " + end + "°";
    }

    /**
     * @param degrees the angle between readings
     * @return null, or what was changed to fit the Environment's laser
     */
    synchronized String setResolution(double degrees) {
        double r = Math.max(0.5, Math.round(degrees * 2) / 2.0);
        resolution = r;
        return r == degrees ? null : "the laser's resolution of " + degrees + "° is taken as " + r + "°";
    }

    /** @return the degrees between the Environment's readings that serve this resolution */
    synchronized double baseIncrement() {
        return resolution % 1 == 0 ? 1 : 0.5;
    }

    /**
     * @param maxRange the laser's range, mm
     * @return the Environment's laser switched as this scan needs
     */
    synchronized Command.ConfigureLaser command(double maxRange) {
        return new Command.ConfigureLaser(on, baseIncrement(), maxRange);
    }

    /**
     * @param scan the Environment's scan, −90° to +90° at {@link #baseIncrement()}
     * @return the packets that carry the part this client asked for, at most
     *         {@value LaserPacket#MAX_READINGS} readings each; none when off or the scan is empty or
     *         of another increment
     */
    synchronized List<LaserPacket> packets(int[] scan) {
        List<LaserPacket> out = new ArrayList<>();
        double base = baseIncrement();
        if (!on || scan.length != (int) Math.round(180 / base) + 1) {
            return out;
        }
        int stride = (int) Math.round(resolution / base);
        int first = (int) Math.round((start + 90) / base);
        int last = (int) Math.round((end + 90) / base);
        int step = (last >= first ? 1 : -1) * stride;
        int[] ranges = new int[Math.abs(last - first) / stride + 1];
        for (int k = 0; k < ranges.length; k++) {
            ranges[k] = scan[first + k * step];
        }
        for (int from = 0; from < ranges.length; from += LaserPacket.MAX_READINGS) {
            int to = Math.min(ranges.length, from + LaserPacket.MAX_READINGS);
            out.add(new LaserPacket(extended, 0, 0, 0, ranges.length, from, Arrays.copyOfRange(ranges, from, to), null));
        }
        return out;
    }
}
