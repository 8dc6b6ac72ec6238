package robosim.aria;

import robosim.protocol.Command;

/**
 * The original simulator's laser, ARIA 2.x's {@code ArSick}: a SICK LMS200 ({@link ArLMS2xx}) named
 * {@code laser}, scanning 180° from 90° right to 90° left of its mounting heading, at 1° (181
 * readings) or 0.5° (361) steps, up to 8000 mm. Newer ARIA programs use {@link ArLMS2xx} through
 * {@link ArLaserConnector}; this class keeps the original's calls.
 *
 * <pre>{@code
 * ArSick sick = new ArSick();
 * robot.addRangeDevice(sick);
 * robot.blockingConnect();
 * if (!sick.blockingConnect()) throw new IllegalStateException(sick.getConnectionError());
 * }</pre>
 */
public class ArSick extends ArLMS2xx {
    /** A laser with buffers of 361 readings (a whole scan at 0.5°) and 200. */
    public ArSick() {
        this(SCAN_READINGS, CUMULATIVE_READINGS);
    }

    /**
     * @param currentBufferSize    how many current readings it keeps
     * @param cumulativeBufferSize how many cumulative readings it keeps (0: none)
     */
    public ArSick(int currentBufferSize, int cumulativeBufferSize) {
        super(1, "laser", currentBufferSize, cumulativeBufferSize);
    }

    /**
     * Sets the angle between readings; sent to the Environment at once if the laser is connected.
     *
     * @param degrees 1 (181 readings a scan) or 0.5 (361)
     * @return true
     * @throws IllegalArgumentException for another value, as the original's did
     */
    @Override
    public boolean setIncrement(double degrees) {
        Command.ConfigureLaser.requireIncrement("increment", degrees);
        return super.setIncrement(degrees);
    }
}
