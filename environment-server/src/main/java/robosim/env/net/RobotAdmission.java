package robosim.env.net;

import robosim.env.core.Simulation;
import robosim.protocol.RobotHello;

/**
 * Which robot hellos the Environment admits: the run's secret (a shared link presented it when it
 * opened), a name by the rule and of the world, the type the world declares, a name not yet taken,
 * and parameters within the physical bounds. A robot may join after the run started (see
 * {@link RobotJoins}). Part of {@link SessionRules}.
 */
final class RobotAdmission {
    private final Simulation sim;
    private final Access access;

    RobotAdmission(Simulation sim, Access access) {
        this.sim = sim;
        this.access = access;
    }

    /**
     * @param c       the connection the hello came on
     * @param hello   the hello
     * @param taken   whether a robot of that name is connected
     * @return why the robot is refused, or null if it is admitted
     */
    String refusal(Connection c, RobotHello hello, boolean taken) {
        String secret = c.isLink() ? null : access.refusal("robot " + RobotHello.printable(hello.name()), hello.token());
        if (secret != null) {
            return secret;
        }
        if (!RobotHello.validName(hello.name())) {
            return RobotHello.NAME_RULE + "; " + RobotHello.quoted(hello.name()) + " is not";
        }
        if (!sim.robotNames().contains(hello.name())) {
            return "world " + sim.world().name() + " has no robot named '" + hello.name() + "'";
        }
        String declared = sim.world().robots().stream().filter(r -> r.name().equals(hello.name()))
                .findFirst().orElseThrow().type();
        if (!declared.equalsIgnoreCase(hello.robotType())) {
            return "robot " + hello.name() + " is a " + declared + " in the world, not a "
                    + SessionRules.printable(hello.robotType());
        }
        if (taken) {
            return "robot " + hello.name() + " is already connected";
        }
        if (hello.parameters() == null) {
            return "robot " + hello.name() + " sent no parameters";
        }
        String bad = hello.parameters().violation();
        return bad == null ? null : "robot " + hello.name() + "'s parameters break a bound: " + bad;
    }
}
