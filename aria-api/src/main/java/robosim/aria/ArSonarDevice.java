package robosim.aria;

import java.util.ArrayList;
import java.util.List;

/**
 * The sonar ring as a range device (ARIA's {@code ArSonarDevice}), named {@code sonar}: each cycle
 * it adds the sonar readings that arrived in that cycle ({@link ArRobot#isSonarNew}) and lie below
 * its maximum range, at the echoes' global positions. A sonar reading at the maximum range means
 * nothing was seen, so it is not an obstacle. Its raw readings ({@link #getRawReadings()}) are
 * copies of the sonar readings new in the latest cycle, in sonar order (ARIA's sonar device keeps
 * none: RoboSim's choice, so that a program can see which transducers fired).
 *
 * <pre>{@code
 * ArSonarDevice sonar = new ArSonarDevice();
 * robot.addRangeDevice(sonar);
 * double ahead = sonar.currentReadingPolar(-20, 20);
 * }</pre>
 */
public class ArSonarDevice extends ArRangeDevice {
    /** The sonar's maximum range, mm. */
    public static final double DEFAULT_MAX_RANGE = 5000;

    /** A sonar device with ARIA's defaults: buffers of 24 and 64 readings, range 5000 mm. */
    public ArSonarDevice() {
        this(DEFAULT_CURRENT_BUFFER_SIZE, DEFAULT_CUMULATIVE_BUFFER_SIZE);
    }

    /**
     * @param currentBufferSize    how many current readings it keeps
     * @param cumulativeBufferSize how many cumulative readings it keeps
     */
    public ArSonarDevice(int currentBufferSize, int cumulativeBufferSize) {
        super("sonar", DEFAULT_MAX_RANGE, currentBufferSize, cumulativeBufferSize);
    }

    /** Adds this cycle's new sonar readings that lie below the maximum range. */
    @Override
    protected void processReadings() {
        ArRobot robot = getRobot();
        if (robot == null) {
            return;
        }
        double max = getMaxRange();
        ArPose pose = robotPose();
        long timeMs = robot.currentState().timeMs();
        List<ArSensorReading> fresh = new ArrayList<>();
        for (int i = 0; i < robot.getNumSonar(); i++) {
            ArSensorReading r = robot.getSonarReading(i);
            if (!robot.isSonarNew(i)) {
                continue;
            }
            fresh.add(r.copy());
            if (r.getRange() < max) {
                addReading(r.getX(), r.getY(), pose, timeMs);
            }
        }
        setRawReadings(fresh);
    }
}
