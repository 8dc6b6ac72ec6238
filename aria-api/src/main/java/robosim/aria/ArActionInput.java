package robosim.aria;

/**
 * Drives as the program (or a person) says from outside the cycle, as ARIA's {@code ArActionInput}
 * (ArActionInput.cpp): it asks each cycle for the velocity set last and for one rotation: a
 * rotational velocity, an absolute heading, or a delta heading from the current heading (asked for
 * once, then 0, so it turns by that much only once). {@link #clear()} asks for nothing again.
 *
 * <pre>{@code
 * ArActionInput input = new ArActionInput();
 * robot.addAction(input, 50);
 * input.setVel(200);
 * input.deltaHeadingFromCurrent(90);
 * }</pre>
 */
public class ArActionInput extends ArAction {
    private enum RotRegime { NONE, ROTVEL, DELTAHEADING, SETHEADING }

    private final ArActionDesired desired = new ArActionDesired();
    private boolean usingVel;
    private double velSet;
    private RotRegime rotRegime = RotRegime.NONE;
    private double rotVal;

    /** An input named {@code Input}. */
    public ArActionInput() {
        this("Input");
    }

    /** @param name the action's name */
    public ArActionInput(String name) {
        super(name, "Inputs vel and heading");
    }

    /** @param vel the translational velocity to ask for, mm/s */
    public synchronized void setVel(double vel) {
        velSet = ActionArgs.finite(getName(), "vel", vel);
        usingVel = true;
    }

    /** @param delta degrees to turn from the heading the robot has when it next fires, once */
    public synchronized void deltaHeadingFromCurrent(double delta) {
        rotVal = ActionArgs.finite(getName(), "delta", delta);
        rotRegime = RotRegime.DELTAHEADING;
    }

    /** @param rotVel the rotational velocity to ask for, deg/s; replaces a heading */
    public synchronized void setRotVel(double rotVel) {
        rotVal = ActionArgs.finite(getName(), "rotVel", rotVel);
        rotRegime = RotRegime.ROTVEL;
    }

    /** @param heading the absolute heading to ask for, degrees; replaces a rotational velocity */
    public synchronized void setHeading(double heading) {
        rotVal = ActionArgs.finite(getName(), "heading", heading);
        rotRegime = RotRegime.SETHEADING;
    }

    /** Asks for neither velocity nor rotation any more. */
    public synchronized void clear() {
        usingVel = false;
        rotRegime = RotRegime.NONE;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        if (usingVel) {
            desired.setVel(velSet);
        }
        switch (rotRegime) {
            case ROTVEL -> desired.setRotVel(rotVal);
            case DELTAHEADING -> {
                desired.setDeltaHeading(rotVal);
                rotVal = 0;
            }
            case SETHEADING -> desired.setHeading(rotVal);
            default -> { }
        }
        return desired;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
