package robosim.remote.robot;

import java.util.List;
import robosim.aria.ArActionKeydrive;
import robosim.aria.ArHeatSensor;
import robosim.aria.ArRobot;
import robosim.aria.ArSick;
import robosim.hw.AbstractRobot;
import robosim.protocol.RobotParameters;
import robosim.remote.KeyDrive;
import robosim.remote.Readings;

/**
 * A Pioneer driven by hand through ARIA's API: {@code setVel}/{@code setRotVel}, {@code stop},
 * {@code move}, {@code setHeading}, {@code enableSonar}/{@code disableSonar}, an {@link ArSick} laser
 * and an {@link ArHeatSensor}. Every call queues a request for the next step (ArRobot's motion calls
 * never block), so the window's thread may make them at any time.
 *
 * <p>With keydrive on, the arrow keys feed an {@link ArActionKeydrive} (ARIA's speeds and
 * increments) added to the robot: each press clears the direct motion of the buttons and fields so
 * that the action drives again, and a stop or a button makes the action forget its speed and turn.
 */
public final class PioneerRemote extends RemoteRobot {
    /** The heat sensor's field of view, degrees: no parameter file names one, so a wide forward cone. */
    public static final double HEAT_FIELD_OF_VIEW = 120;
    /** The heat sensor's range, mm, matching a Pioneer's sonar range. */
    public static final double HEAT_RANGE = 5000;
    /** The keydrive action's priority. */
    public static final int KEYDRIVE_PRIORITY = 50;

    private final ArRobot robot;
    private final ArSick laser = new ArSick();
    private final ArHeatSensor heat = new ArHeatSensor(HEAT_FIELD_OF_VIEW, HEAT_RANGE);
    private volatile boolean heatOn;
    private final ArActionKeydrive keydrive;

    /** @param robot a connected robot; its laser is attached here and starts off */
    public PioneerRemote(ArRobot robot) {
        this(robot, false);
    }

    /**
     * @param robot    a connected robot; its laser is attached here and starts off
     * @param keydrive whether the arrow keys feed an {@link ArActionKeydrive}, added to the robot here
     */
    public PioneerRemote(ArRobot robot, boolean keydrive) {
        this.robot = robot;
        robot.addRangeDevice(laser);
        this.keydrive = keydrive ? new ArActionKeydrive() : null;
        if (keydrive) {
            robot.addAction(this.keydrive, KEYDRIVE_PRIORITY);
        }
    }

    /**
     * Connects a Pioneer; the calling thread becomes the robot's program, so call {@link #run()} on it.
     *
     * @param name       the robot's name in the world
     * @param host       the Environment's host
     * @param port       the Environment's robot port
     * @param parameters the robot's parameters
     * @return the connected robot
     * @throws IllegalStateException saying why it could not connect
     */
    public static PioneerRemote connect(String name, String host, int port, RobotParameters parameters) {
        return connect(name, host, port, parameters, false);
    }

    /**
     * Connects a Pioneer, its arrow keys feeding an {@link ArActionKeydrive} or not.
     *
     * @param name       the robot's name in the world
     * @param host       the Environment's host
     * @param port       the Environment's robot port
     * @param parameters the robot's parameters
     * @param keydrive   whether the arrow keys feed a keydrive action
     * @return the connected robot
     * @throws IllegalStateException saying why it could not connect
     */
    public static PioneerRemote connect(String name, String host, int port, RobotParameters parameters,
            boolean keydrive) {
        ArRobot robot = new ArRobot(name, host, port, parameters);
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("robot " + name + " could not connect to " + host + ":" + port + ": "
                    + robot.getConnectionError());
        }
        robot.enableMotors(); // a Pioneer's motors are disabled when its program connects, as in ARIA
        return new PioneerRemote(robot, keydrive);
    }

    @Override
    protected AbstractRobot robot() {
        return robot;
    }

    @Override
    protected boolean awaitStep() {
        robot.sleepSimulated(robot.getStepMs());
        return robot.isConnected();
    }

    @Override
    protected Readings read() {
        RobotParameters p = robot.getParameters();
        boolean sonarOn = robot.areSonarsEnabled();
        int[] ranges = new int[robot.getNumSonar()];
        for (int i = 0; i < ranges.length; i++) {
            // a sonar that never reported has nothing to draw yet
            ranges[i] = robot.getSonarReading(i) != null && robot.getSonarReading(i).getCounterTaken() > 0
                    ? robot.getSonarRange(i) : -1;
        }
        boolean laserOn = laser.isConnected();
        List<Readings.Point> hits = laserOn ? Readings.laserHits(p, laser.getRawScan(), laser.getMaxRange()) : List.of();
        Readings.Heat h = heatOn ? new Readings.Heat(heat.getIntensity(), heat.getBearing(), heat.getDistance()) : null;
        return new Readings(robot.getStep(), robot.getSimTimeMs(), robot.getX(), robot.getY(), robot.getTh(),
                robot.getVel(), robot.getRotVel(), robot.isStalled(), sonarOn,
                sonarOn ? Readings.sonarRays(p, ranges) : List.of(), laserOn, hits, h,
                Math.max(p.sonarMaxRange(), laserOn ? laser.getMaxRange() : 0));
    }

    @Override
    public void drive(double vel, double rotVel) {
        forgetKeydrive();
        robot.setVel(vel);
        robot.setRotVel(rotVel);
    }

    @Override
    public void stop() {
        forgetKeydrive();
        robot.stop();
    }

    @Override
    public boolean keydrive() {
        return keydrive != null;
    }

    @Override
    public void keydrive(KeyDrive.Key key) {
        if (keydrive == null) {
            throw new UnsupportedOperationException("robot " + name() + " was not started with keydrive");
        }
        robot.clearDirectMotion();
        switch (key) {
            case FORWARD -> keydrive.up();
            case BACK -> keydrive.down();
            case LEFT -> keydrive.left();
            default -> keydrive.right();
        }
    }

    /** A direct command takes over: the keydrive action starts again from standing still. */
    private void forgetKeydrive() {
        if (keydrive != null) {
            keydrive.space();
        }
    }

    @Override
    public void move(double distance) {
        forgetKeydrive();
        robot.move(distance);
    }

    @Override
    public void setHeading(double heading) {
        forgetKeydrive();
        robot.setHeading(heading);
    }

    @Override
    public void sonar(boolean on) {
        if (on) {
            robot.enableSonar();
        } else {
            robot.disableSonar();
        }
    }

    @Override
    public String laser(boolean on) {
        if (!on) {
            laser.disconnect();
            return null;
        }
        return laser.blockingConnect() ? null : laser.getConnectionError();
    }

    @Override
    public String heat(boolean on) {
        if (on && !heatOn) {
            heat.attach(robot);
        } else if (!on && heatOn) {
            heat.detach();
        }
        heatOn = on;
        return null;
    }
}
