package robosim.examples.meetup;

import robosim.aria.ArMath;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;
import robosim.hw.RobotMessage;

/**
 * Two robots talking over comms: each tells its peer where it is every {@link #EVERY} steps (a
 * {@link Position} sent to the peer by name) and drives towards where the peer said it was. A robot
 * stops within {@link #NEAR} mm of the peer's last position, and leaves the run once it has stood
 * there for a second. Run the same program for both robots, each naming the other.
 *
 * <p>Run it as {@code bin/robosim robot robosim.examples.meetup.MeetUp NAME HOST PORT PEER}.
 */
public final class MeetUp {
    /** How near to the peer a robot stops, mm between the centres. */
    public static final double NEAR = 1000;
    /** How often a robot tells its peer where it is, steps. */
    public static final int EVERY = 2;
    private static final int STAND_STEPS = 10;

    private final ArRobot robot;
    private final String peer;
    private Position peerAt;
    private int heard;

    /**
     * @param robot a connected robot
     * @param peer  the other robot's name
     */
    public MeetUp(ArRobot robot, String peer) {
        this.robot = robot;
        this.peer = peer;
    }

    /**
     * Runs one of the two robots until it has met its peer.
     *
     * @param args NAME HOST PORT PEER
     */
    public static void main(String[] args) {
        if (args.length != 4) {
            throw new IllegalArgumentException("usage: MeetUp NAME HOST PORT PEER");
        }
        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("robot " + args[0] + " could not connect: " + robot.getConnectionError());
        }
        robot.enableMotors(); // a Pioneer's motors are disabled when its program connects, as in ARIA
        int heard = new MeetUp(robot, args[3]).run();
        System.out.println(args[0] + " met " + args[3] + " after hearing from it " + heard + " times");
        robot.disconnect();
    }

    /**
     * Talks and drives until the robot has stood near its peer for a second, or is disconnected.
     *
     * @return how many positions it heard from its peer
     */
    public int run() {
        int standing = 0;
        for (long step = 0; robot.isConnected() && standing < STAND_STEPS; step++) {
            if (step % EVERY == 0) {
                robot.send(peer, new Position(robot.getX(), robot.getY()));
            }
            RobotMessage m;
            while ((m = robot.poll()) != null) {
                if (m.holds(Position.class)) {
                    peerAt = m.as(Position.class);
                    heard++;
                }
            }
            standing = steer() ? standing + 1 : 0;
            ArUtil.sleep(robot.getStepMs());
        }
        robot.stop();
        return heard;
    }

    /** @return whether the robot stands near the peer's last known position */
    private boolean steer() {
        if (peerAt == null) {
            return false;
        }
        double dx = peerAt.x() - robot.getX();
        double dy = peerAt.y() - robot.getY();
        double distance = Math.hypot(dx, dy);
        if (distance <= NEAR) {
            robot.setVel(0);
            robot.setRotVel(0);
            return true;
        }
        double error = ArMath.subAngle(Math.toDegrees(Math.atan2(dy, dx)), robot.getTh());
        robot.setRotVel(Math.max(-40, Math.min(40, 1.5 * error)));
        // slow down on the way in: the peer's position is a few steps old, and the peer comes closer too
        robot.setVel(Math.abs(error) > 30 ? 0 : Math.min(300, (distance - NEAR) / 2 + 50));
        return false;
    }
}
