package robosim.env.net;

import java.util.List;
import java.util.Locale;
import robosim.env.core.Simulation;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotKind;

/**
 * Which robot hellos the Environment admits: the run's secret (a shared link presented it when it
 * opened), a name by the rule and of the world (or, in an open world, any name within
 * {@code --max-robots}, of a type in {@link #SPAWN_TYPES}), the type the world declares, a name not
 * yet taken, and parameters within the physical bounds. A robot may join after the run started (see
 * {@link RobotJoins}). Part of {@link SessionRules}.
 */
final class RobotAdmission {
    /** The types a robot the world does not name may be: those a world file may name. */
    static final List<String> SPAWN_TYPES = RobotKind.ids();

    private final CurrentRun run;
    private final Access access;
    private final int maxRobots;

    RobotAdmission(CurrentRun run, Access access, int maxRobots) {
        this.run = run;
        this.access = access;
        this.maxRobots = maxRobots;
    }

    private Simulation sim() {
        return run.sim();
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
        if (!sim().robotNames().contains(hello.name())) {
            String newcomer = newcomer(hello);
            if (newcomer != null) {
                return newcomer;
            }
        } else if (!sim().type(hello.name()).equalsIgnoreCase(hello.robotType())) {
            String declared = sim().type(hello.name());
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

    /** @return why a robot the world does not name is refused, or null if an open world may take it */
    private String newcomer(RobotHello hello) {
        if (!sim().world().rules().open()) {
            return "world " + sim().world().name() + " has no robot named '" + hello.name() + "'";
        }
        String type = hello.robotType() == null ? "" : hello.robotType().toLowerCase(Locale.ROOT);
        if (!SPAWN_TYPES.contains(type)) {
            return "robot " + hello.name() + " is a " + SessionRules.printable(hello.robotType())
                    + "; an open world admits " + String.join(" and ", SPAWN_TYPES) + " robots";
        }
        if (sim().robotNames().size() >= maxRobots) {
            return "world " + sim().world().name() + " has " + sim().robotNames().size()
                    + " robots, the most this Environment admits (--max-robots)";
        }
        return null;
    }
}
