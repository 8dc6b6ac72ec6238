package robosim.remote.robot;

import java.util.List;
import robosim.hw.AbstractRobot;
import robosim.protocol.RobotParameters;
import robosim.remote.Readings;
import robosim.scout.NomadUnits;
import robosim.scout.Scout;
import robosim.scout.StateVector;

/**
 * A Nomadic Scout driven by hand through its own API, in its units (1/10 inch, 1/10 degree):
 * {@code scout_vm} drives, {@code st} stops, {@code pr} moves and turns to a heading, {@code conf_sn}
 * switches the sonars, and {@code gs} waits for each step's state. A Scout has no laser and no heat
 * sensor.
 */
public final class ScoutRemote extends RemoteRobot {
    /** Every sonar, in ring order, at the fastest rate: the Scout's default firing. */
    private static final int[] ALL_SONARS = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};

    private final Scout scout;
    private volatile boolean sonarOn = true;

    /** @param scout a connected Scout */
    public ScoutRemote(Scout scout) {
        this.scout = scout;
    }

    /**
     * Connects a Scout; the calling thread becomes the robot's program, so call {@link #run()} on it.
     *
     * @param name       the robot's name in the world
     * @param host       the Environment's host
     * @param port       the Environment's robot port
     * @param parameters the robot's parameters
     * @return the connected robot
     * @throws IllegalStateException saying why it could not connect
     */
    public static ScoutRemote connect(String name, String host, int port, RobotParameters parameters) {
        Scout scout = new Scout(name, host, port, parameters);
        if (!scout.connect_robot()) {
            throw new IllegalStateException("robot " + name + " could not connect to " + host + ":" + port + ": "
                    + scout.getConnectionError());
        }
        return new ScoutRemote(scout);
    }

    @Override
    protected AbstractRobot robot() {
        return scout;
    }

    @Override
    protected boolean awaitStep() {
        return scout.gs() && scout.isConnected();
    }

    @Override
    protected Readings read() {
        long[] s = scout.State;
        double th = NomadUnits.tenthDegToDeg(s[StateVector.STATE_CONF_STEER]);
        double right = NomadUnits.tenthInchToMm(s[StateVector.STATE_VEL_RIGHT]);
        double left = NomadUnits.tenthInchToMm(s[StateVector.STATE_VEL_LEFT]);
        // scout_vm's rule, turned round: the wheels differ by 2 · steer · ROTATION_CONSTANT (1/10 inch, 1/10 degree)
        double rotVel = (right - left) / NomadUnits.MM_PER_TENTH_INCH / (2 * Scout.ROTATION_CONSTANT) / 10;
        int[] ranges = new int[StateVector.SONARS];
        for (int i = 0; i < ranges.length; i++) {
            ranges[i] = (int) Math.round(NomadUnits.inchesToMm(s[StateVector.STATE_SONAR_0 + i]));
        }
        boolean on = sonarOn;
        return new Readings(scout.getStep(), scout.getSimTimeMs(), NomadUnits.tenthInchToMm(s[StateVector.STATE_CONF_X]),
                NomadUnits.tenthInchToMm(s[StateVector.STATE_CONF_Y]), th > 180 ? th - 360 : th, (right + left) / 2, rotVel,
                s[StateVector.STATE_BUMPER] != 0, on, on ? Readings.sonarRays(parameters(), ranges) : List.of(),
                false, List.of(), null, parameters().sonarMaxRange());
    }

    @Override
    public void drive(double vel, double rotVel) {
        scout.scout_vm((int) NomadUnits.mmToTenthInch(vel), (int) NomadUnits.degToTenthDeg(rotVel));
    }

    @Override
    public void stop() {
        scout.st();
    }

    @Override
    public void move(double distance) {
        int d = (int) NomadUnits.mmToTenthInch(distance);
        scout.pr(d, d, 0);
    }

    /** Turns on the spot by the shorter way: the Nomad API has no absolute turn, so the wheels move apart. */
    @Override
    public void setHeading(double heading) {
        Readings r = latest();
        double now = r == null ? 0 : r.th();
        double delta = Math.IEEEremainder(heading - now, 360);
        int wheel = (int) Math.round(NomadUnits.degToTenthDeg(delta) * Scout.ROTATION_CONSTANT);
        scout.pr(wheel, -wheel, 0);
    }

    @Override
    public void sonar(boolean on) {
        sonarOn = on;
        scout.conf_sn(1, on ? ALL_SONARS : new int[] {StateVector.ORDER_END});
    }

    @Override
    public String laser(boolean on) {
        return on ? "a Scout has no laser" : null;
    }

    @Override
    public String heat(boolean on) {
        return on ? "a Scout has no heat sensor" : null;
    }
}
