package robosim.aria;

/**
 * Drives from the joystick plugged into the robot, as ARIA's {@code ArActionRobotJoydrive}
 * (ArActionRobotJoydrive.cpp): on connecting it asks the robot for joystick packets
 * ({@code JOYINFO} 2) and reads each (id 0xF8: two buttons, X, Y and throttle, 0 to 1023); with the
 * deadman (button 1) held, or without it when {@code requireDeadmanPushed} is false, a stick beyond
 * a third of its travel gives velocity and rotational velocity as that fraction of the robot's
 * maximums times the throttle, a stick in the middle a stop (once, without the deadman).
 *
 * <p><b>In the simulator:</b> the simulated robots have no joystick and send no joystick packets
 * (RoboSim's protocol has none), so no button is ever down: the action wants nothing, as ARIA's does
 * until a packet comes. With {@code requireDeadmanPushed} false, ARIA's reads whatever its fields
 * held before a packet (it leaves them unset); here the stick starts centred, so the action asks for
 * a stop once, as a centred stick does in ARIA, and then nothing. Nothing is asked of the robot on
 * connecting: it has no joystick to report.
 * {@link #handleJoystickPacket} takes a packet's values, for a program that has them from elsewhere.
 */
public class ArActionRobotJoydrive extends ArAction {
    /** The centre of the stick's range, as in a robot's joystick packet. */
    static final int CENTRE = 512;

    private final ArActionDesired desired = new ArActionDesired();
    private boolean requireDeadmanPushed;
    private boolean deadZoneLast;
    private int button1;
    private int button2;
    private int joyX = CENTRE;
    private int joyY = CENTRE;
    private int throttle;

    /** ARIA's defaults: "robotJoyDrive", the deadman required. */
    public ArActionRobotJoydrive() {
        this("robotJoyDrive");
    }

    /** @param name the action's name */
    public ArActionRobotJoydrive(String name) {
        this(name, true);
    }

    /**
     * @param name                 the action's name
     * @param requireDeadmanPushed whether button 1 must be held to drive
     */
    public ArActionRobotJoydrive(String name, boolean requireDeadmanPushed) {
        super(name, "This action reads the joystick on the robot and sets the translational and rotational"
                + " velocities based on this.");
        this.requireDeadmanPushed = requireDeadmanPushed;
        setNextArgument(ArArg.ofBool("whether to require the deadman to be pushed or not",
                () -> this.requireDeadmanPushed, v -> this.requireDeadmanPushed = v,
                "If this is true then deadman will need to be pushed to drive, if false we'll drive based on the"
                        + " joystick all the time"));
    }

    /**
     * A joystick packet's values, as ARIA's packet handler reads them.
     *
     * @param button1  the first button (the deadman), nonzero when held
     * @param button2  the second button
     * @param joyX     X, 0 to 1023 (512 centred, low to the right)
     * @param joyY     Y, 0 to 1023 (512 centred, high forwards)
     * @param throttle the throttle, 0 to 1023
     */
    public synchronized void handleJoystickPacket(int button1, int button2, int joyX, int joyY, int throttle) {
        this.button1 = button1;
        this.button2 = button2;
        this.joyX = joyX;
        this.joyY = joyY;
        this.throttle = throttle;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        if (requireDeadmanPushed && button1 == 0) {
            deadZoneLast = false;
            return null;
        }
        double ratioRot = -(joyX - CENTRE) / 512.0;
        double ratioTrans = (joyY - CENTRE) / 512.0;
        double ratioThrottle = throttle / 1024.0;
        boolean doTrans = Math.abs(ratioTrans) > .33;
        boolean doRot = Math.abs(ratioRot) > .33;
        if (!doTrans && !doRot) {
            if (deadZoneLast && !requireDeadmanPushed) {
                return null;
            }
            desired.setVel(0);
            desired.setDeltaHeading(0);
            deadZoneLast = true;
            return desired;
        }
        deadZoneLast = false;
        double vel = myRobot.getVel();
        if (doTrans && ((vel > 0 && ratioTrans < -0.5) || (vel < 0 && ratioTrans > 0.5))) {
            desired.setTransDecel(myRobot.getTransDecel() * 3);
        }
        double rotVel = myRobot.getRotVel();
        if (doRot && ((rotVel > 0 && ratioRot < -0.5) || (rotVel < 0 && ratioRot > 0.5))) {
            desired.setRotDecel(myRobot.getRotDecel() * 3);
        }
        desired.setVel(doTrans ? ratioTrans * ratioThrottle * myRobot.getTransVelMax() : 0);
        desired.setRotVel(doRot ? ratioRot * ratioThrottle * myRobot.getRotVelMax() : 0);
        return desired;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }

    /** @return the second button's last value (ARIA keeps it; no action uses it) */
    synchronized int getButton2() {
        return button2;
    }
}
