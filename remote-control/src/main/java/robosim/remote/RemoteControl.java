package robosim.remote;

import java.util.Locale;

/**
 * What each of the window's controls sends to the robot: the drive buttons, the arrow keys (see
 * {@link KeyDrive}), the speed sliders, the move and heading fields, the sensor switches and the send
 * box. Each action returns the line the window's status shows (what was sent), or throws
 * {@link IllegalArgumentException} naming a bad field. Used from one thread, the window's.
 *
 * <p>The buttons latch (forward drives until stop or another button); the keys drive only while
 * held, as ARIA's keyboard teleop does. When the target drives by an ARIA keydrive action
 * ({@link DriveTarget#keydrive()}, {@code robosim remote --keydrive}), each key press goes to that
 * action instead, as ARIA's key handler feeds {@code ArActionKeydrive}.
 */
public final class RemoteControl {
    /** The drive buttons. */
    public enum Button {
        /** Forward at the translational speed. */
        FORWARD,
        /** Back at the translational speed. */
        BACK,
        /** Turn left on the spot at the rotational speed. */
        LEFT,
        /** Turn right on the spot at the rotational speed. */
        RIGHT,
        /** Stop. */
        STOP
    }

    private final DriveTarget target;
    private final SpeedLimits limits;
    private final KeyDrive keys = new KeyDrive();
    private int vel;
    private int rotVel;
    /** What the buttons last asked for, re-sent when a slider moves; null when stopped by hand. */
    private Button latched;

    /** @param target the robot driven */
    public RemoteControl(DriveTarget target) {
        this.target = target;
        this.limits = SpeedLimits.of(target.parameters());
        this.vel = limits.vel();
        this.rotVel = limits.rotVel();
    }

    /** @return whether the arrow keys feed the robot's keydrive action rather than drive while held */
    public boolean keydrive() {
        return target.keydrive();
    }

    /** @return the sliders' bounds and starts */
    public SpeedLimits limits() {
        return limits;
    }

    /** @return the translational speed the buttons and keys drive at, mm/s */
    public int vel() {
        return vel;
    }

    /** @return the rotational speed the buttons and keys turn at, deg/s */
    public int rotVel() {
        return rotVel;
    }

    /**
     * @param button the button pressed
     * @return what was sent
     */
    public String button(Button button) {
        keys.clear();
        if (button == Button.STOP) {
            latched = null;
            target.stop();
            return "sent: stop";
        }
        latched = button;
        return drive(switch (button) {
            case FORWARD -> new KeyDrive.Drive(vel, 0);
            case BACK -> new KeyDrive.Drive(-vel, 0);
            case LEFT -> new KeyDrive.Drive(0, rotVel);
            default -> new KeyDrive.Drive(0, -rotVel);
        });
    }

    /**
     * @param key   an arrow key pressed (or auto-repeated)
     * @param nowMs the time, ms
     * @return what was sent, or null when nothing changed
     */
    public String keyPressed(KeyDrive.Key key, long nowMs) {
        latched = null;
        if (target.keydrive()) {
            keys.clear();
            target.keydrive(key);
            return "sent: keydrive " + key.name().toLowerCase(Locale.ROOT);
        }
        return keys.press(key, nowMs) ? driveKeys() : null;
    }

    /**
     * @param key   an arrow key released: it counts after {@link KeyDrive#RELEASE_GRACE_MS}, at a {@link #tick}
     * @param nowMs the time, ms
     */
    public void keyReleased(KeyDrive.Key key, long nowMs) {
        keys.release(key, nowMs);
    }

    /**
     * Lets go of the keys released long enough ago; the window calls it on a timer.
     *
     * @param nowMs the time, ms
     * @return what was sent, or null when nothing changed
     */
    public String tick(long nowMs) {
        return keys.due(nowMs) ? driveKeys() : null;
    }

    /**
     * The window lost the keyboard: no key release will come, so keys held count as released now.
     *
     * @return what was sent (a stop), or null when no key was held
     */
    public String keysLost() {
        if (!keys.anyHeld()) {
            return null;
        }
        keys.clear();
        target.stop();
        return "sent: stop (the window lost the keyboard)";
    }

    /** @return whether a key release waits for a {@link #tick} */
    public boolean releasePending() {
        return keys.releasePending();
    }

    private String driveKeys() {
        KeyDrive.Drive d = keys.drive(vel, rotVel);
        if (d.isStop()) {
            target.stop();
            return "sent: stop (keys released)";
        }
        return drive(d);
    }

    private String drive(KeyDrive.Drive d) {
        target.drive(d.vel(), d.rotVel());
        return String.format(Locale.ROOT, "sent: vel %.0f mm/s, rotVel %.0f deg/s", d.vel(), d.rotVel());
    }

    /**
     * @param speed the translational slider's value, mm/s: clamped to the robot's limit
     * @return what was sent when the robot is driving (at the new speed), else null
     */
    public String setVel(int speed) {
        vel = limits.clampVel(speed);
        return resend();
    }

    /**
     * @param speed the rotational slider's value, deg/s: clamped to the robot's limit
     * @return what was sent when the robot is driving (at the new speed), else null
     */
    public String setRotVel(int speed) {
        rotVel = limits.clampRotVel(speed);
        return resend();
    }

    private String resend() {
        if (keys.anyHeld()) {
            return driveKeys();
        }
        if (latched != null) {
            return button(latched);
        }
        return null;
    }

    /**
     * @param distance the move-distance field
     * @return what was sent
     * @throws IllegalArgumentException if the field is not a distance (see {@link DriveFields#distance})
     */
    public String move(String distance) {
        double d = DriveFields.distance(distance);
        keys.clear();
        latched = null;
        target.move(d);
        return String.format(Locale.ROOT, "sent: move %.0f mm", d);
    }

    /**
     * @param heading the heading field
     * @return what was sent
     * @throws IllegalArgumentException if the field is not a heading (see {@link DriveFields#heading})
     */
    public String heading(String heading) {
        double h = DriveFields.heading(heading);
        keys.clear();
        latched = null;
        target.setHeading(h);
        return String.format(Locale.ROOT, "sent: heading %.1f°", h);
    }

    /** @param on sonar on or off @return what was sent */
    public String sonar(boolean on) {
        target.sonar(on);
        return "sent: sonar " + (on ? "on" : "off");
    }

    /** @param on laser on or off @return what was sent, or why not */
    public String laser(boolean on) {
        String why = target.laser(on);
        return why == null ? "sent: laser " + (on ? "on" : "off") : "laser: " + why;
    }

    /** @param on heat sensor on or off @return what was sent, or why not */
    public String heat(boolean on) {
        String why = target.heat(on);
        return why == null ? "sent: heat " + (on ? "on" : "off") : "heat: " + why;
    }

    /**
     * @param to   who the message goes to
     * @param name the robot or group field
     * @param text the text field
     * @return what was sent
     * @throws IllegalArgumentException if a field breaks its rule (see {@link MessageDraft#of})
     */
    public String send(MessageDraft.To to, String name, String text) {
        MessageDraft m = MessageDraft.of(to, name, text);
        target.send(m);
        return "sent: message to " + m.recipient();
    }
}
