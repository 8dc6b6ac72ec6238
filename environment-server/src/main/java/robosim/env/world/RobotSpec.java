package robosim.env.world;

import java.nio.file.Path;
import robosim.geometry.BodyShape;
import robosim.geometry.Pose2D;
import robosim.protocol.RobotParameters;

/**
 * A robot that must connect before the run starts, with its start pose and the parameters read
 * from its parameter file (which give it its size).
 *
 * @param name          unique within the world; the robot connects under this name
 * @param type          the robot API it is written against; {@code pioneer} for now
 * @param x             start x of the centre of rotation, mm
 * @param y             start y of the centre of rotation, mm
 * @param th            start heading, degrees, counter-clockwise from +x
 * @param parameterFile the robot parameter file, resolved against the world file's directory
 * @param parameters    what the parameter file says
 * @param line          the 1-based line of its {@code <robot>} element in the world file
 */
public record RobotSpec(String name, String type, double x, double y, double th,
                        Path parameterFile, RobotParameters parameters, int line) {

    /** @return the robot's body: the rectangle its parameter file gives */
    public BodyShape body() {
        return bodyOf(parameters);
    }

    /**
     * The body a robot's parameters describe: a rectangle (length front and rear, width), or for a
     * round robot a 24-sided polygon whose sides touch the circle of its radius.
     *
     * @param p the robot's parameters
     * @return its body
     */
    public static BodyShape bodyOf(RobotParameters p) {
        if (p.isRound()) {
            return BodyShape.disc(p.robotRadius(), ROUND_SIDES);
        }
        return BodyShape.rectangle(p.robotLengthFront(), p.robotLengthRear(), p.robotWidth());
    }

    /** The sides of the polygon a round body is simulated as. */
    public static final int ROUND_SIDES = 24;

    /** @return the start pose, with the heading in radians as {@link Pose2D} has it */
    public Pose2D pose() {
        return new Pose2D(x, y, Math.toRadians(th));
    }
}
