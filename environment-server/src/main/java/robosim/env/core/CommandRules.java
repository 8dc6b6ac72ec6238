package robosim.env.core;

import robosim.protocol.Command;

/**
 * What a robot may ask for: every number finite, ranges and fields of view positive, a laser
 * increment a SICK LMS200 has. A robot that asks for anything else is closed by the server before
 * the request reaches the simulation.
 */
public final class CommandRules {
    private CommandRules() {
    }

    /**
     * @param c a command from a robot
     * @return what is wrong with it, or null if nothing is
     */
    public static String problem(Command c) {
        if (c instanceof Command.SetVel v) {
            return finite("vel", v.vel());
        } else if (c instanceof Command.SetRotVel v) {
            return finite("rotVel", v.rotVel());
        } else if (c instanceof Command.SetVel2 v) {
            return first(finite("left", v.left()), finite("right", v.right()));
        } else if (c instanceof Command.Move m) {
            return finite("distance", m.distance());
        } else if (c instanceof Command.SetHeading h) {
            return finite("heading", h.heading());
        } else if (c instanceof Command.SetDeltaHeading h) {
            return finite("delta", h.delta());
        } else if (c instanceof Command.MoveWheels m) {
            return first(finite("left", m.left()), finite("right", m.right()));
        } else if (c instanceof Command.SetAccel a) {
            return first(positive("trans accel", a.trans()), positive("rot accel", a.rot()));
        } else if (c instanceof Command.SetMaxTransVel v) {
            return finite("maxVel", v.vel());
        } else if (c instanceof Command.SetMaxRotVel v) {
            return finite("maxRotVel", v.rotVel());
        } else if (c instanceof Command.ConfigureLaser l) {
            if (l.increment() != 1 && l.increment() != 0.5) {
                return l.increment() + " was supplied for the laser increment: a SICK LMS200 scans at 1 or 0.5 degrees";
            }
            return positive("laser maxRange", l.maxRange());
        } else if (c instanceof Command.SendMessage m) {
            if (m.mode() == null || m.kind() == null || m.body() == null) {
                return "message " + m.id() + " needs a mode, a kind and a body";
            }
            return m.mode() != Command.Addressing.ALL && (m.to() == null || m.to().isBlank())
                    ? "message " + m.id() + " is addressed to a " + m.mode().name().toLowerCase() + " but names none" : null;
        } else if (c instanceof Command.JoinGroup j) {
            return j.group() == null || j.group().isBlank() ? "a group to join needs a name" : null;
        } else if (c instanceof Command.LeaveGroup l) {
            return l.group() == null || l.group().isBlank() ? "a group to leave needs a name" : null;
        } else if (c instanceof Command.Say say) {
            return say.text() == null || say.text().length() > 1000
                    ? "a robot says at most 1000 characters, not " + (say.text() == null ? "nothing" : say.text().length()) : null;
        } else if (c instanceof Command.ReportFound f) {
            return f.object() == null || f.object().isBlank() ? "a report of a find needs the object's name" : null;
        } else if (c instanceof Command.ConfigureHeatSensor h) {
            return first(positive("heat fieldOfView", h.fieldOfView()), positive("heat maxRange", h.maxRange()),
                    h.fieldOfView() > 360 ? h.fieldOfView() + " was supplied for heat fieldOfView: at most 360 degrees" : null);
        }
        return null;
    }

    private static String finite(String name, double v) {
        return Double.isFinite(v) ? null : v + " was supplied for " + name + ": it must be a finite number";
    }

    private static String positive(String name, double v) {
        return Double.isFinite(v) && v > 0 ? null : v + " was supplied for " + name + ": it must be greater than 0";
    }

    private static String first(String... problems) {
        for (String p : problems) {
            if (p != null) {
                return p;
            }
        }
        return null;
    }
}
