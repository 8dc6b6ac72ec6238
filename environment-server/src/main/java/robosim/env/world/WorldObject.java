package robosim.env.world;

/**
 * A small round movable object of the world (a puck), as its {@code <object>} element gives it:
 * robots' sonar and laser see it, a robot driving into it pushes it, and a robot's gripper can
 * pick it up and carry it.
 *
 * @param type   its type: {@value #PUCK}, the only one so far
 * @param x      where it starts, mm
 * @param y      where it starts, mm
 * @param radius mm, from {@value #MIN_RADIUS} to {@value #MAX_RADIUS}
 * @param color  its colour as the world file names it (for cameras and viewers), or null
 * @param line   the line of its element in the world file
 */
public record WorldObject(String type, double x, double y, double radius, String color, int line) {
    /** The type of a puck. */
    public static final String PUCK = "puck";
    /**
     * A puck's radius when the world file gives none, mm: a hockey puck's 76 mm across, the size
     * of the pucks a Pioneer gripper was made for.
     */
    public static final double DEFAULT_RADIUS = 38;
    /** The smallest radius of an object, mm. */
    public static final double MIN_RADIUS = 10;
    /** The largest radius of an object, mm: it must still fit between a gripper's open paddles. */
    public static final double MAX_RADIUS = 100;
}
