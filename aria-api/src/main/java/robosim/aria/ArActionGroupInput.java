package robosim.aria;

/**
 * The program's own velocity and heading, guarded, as ARIA's {@code ArActionGroupInput}
 * (ArActionGroups.cpp): ARIA's table-sensor limiter (100), a forward limiter "Speed Limiter Near"
 * (stop 300 mm, slow from 600 mm, 250 mm/s; 90), a forward limiter "Speed Limiter Far" (300 mm,
 * 1100 mm, 400 mm/s; 89), a backward limiter (80) and an {@link ArActionInput} (70) that the group's
 * {@link #setVel}, {@link #setRotVel}, {@link #setHeading}, {@link #deltaHeadingFromCurrent} and
 * {@link #clear} set. Meant to be used one group at a time ({@link #activateExclusive()}).
 *
 * <p>The table-sensor limiter wants nothing on the simulated robots, which have no table sensors
 * ({@link ArActionLimiterTableSensor}).
 */
public final class ArActionGroupInput extends ArActionGroup {
    private final ArActionInput input;

    /** @param robot the robot its actions are added to */
    public ArActionGroupInput(ArRobot robot) {
        super(robot);
        addAction(new ArActionLimiterTableSensor(), 100);
        addAction(new ArActionLimiterForwards("Speed Limiter Near", 300, 600, 250), 90);
        addAction(new ArActionLimiterForwards("Speed Limiter Far", 300, 1100, 400), 89);
        addAction(new ArActionLimiterBackwards(), 80);
        input = new ArActionInput();
        addAction(input, 70);
    }

    /** @param vel the velocity wanted, mm/s */
    public void setVel(double vel) {
        input.setVel(vel);
    }

    /** @param rotVel the rotational velocity wanted, deg/s */
    public void setRotVel(double rotVel) {
        input.setRotVel(rotVel);
    }

    /** @param heading the absolute heading wanted, degrees */
    public void setHeading(double heading) {
        input.setHeading(heading);
    }

    /** @param delta a turn from the current heading, degrees */
    public void deltaHeadingFromCurrent(double delta) {
        input.deltaHeadingFromCurrent(delta);
    }

    /** Nothing wanted any more. */
    public void clear() {
        input.clear();
    }

    /** @return its input action */
    public ArActionInput getActionInput() {
        return input;
    }
}
