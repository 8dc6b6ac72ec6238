package robosim.env.net;

import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.logging.Logger;
import robosim.env.core.Simulation;
import robosim.geometry.Pose2D;
import robosim.protocol.Bye;
import robosim.protocol.LogLimiter;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotParameters;
import robosim.protocol.Welcome;

/**
 * A robot's hello, part of {@link SessionRules}: admitted or refused ({@link RobotAdmission}), and
 * once admitted given its body's parameters and welcomed with its state. Before the run starts a
 * robot's program brings its own parameters (a gripper the world gives the body stays: see
 * {@code keepingGripper}); after, a robot joins its body as it is (where it stood
 * still since it went, with its odometry), so its program must bring the parameters that body has:
 * a body does not change shape or limits during a run. A robot admitted while a step is open takes
 * part from the next step opened.
 */
final class RobotJoins {
    private static final Logger LOG = Logger.getLogger(SessionRules.class.getName());

    private final CurrentRun run;
    private final RobotAdmission admission;
    private final Departures departures;
    private final Refusals refusals;
    private final LogLimiter limited;
    /** The first step each robot took part in since it was last welcomed. */
    private final Map<String, Long> firstSteps = new HashMap<>();
    private boolean worldChanged;

    RobotJoins(CurrentRun run, Access access, Limits limits, Departures departures, Refusals refusals,
               LogLimiter limited) {
        this.limited = limited;
        this.run = run;
        this.admission = new RobotAdmission(run, access, limits.maxRobots());
        this.departures = departures;
        this.refusals = refusals;
    }

    private Simulation sim() {
        return run.sim();
    }

    /**
     * @param robot a robot connected
     * @param step  a step of the run
     * @return the robot's own count of that step: 1 for the first step it takes part in since it was
     *         welcomed (a robot that joins late, or again, starts again from 1)
     */
    long robotStep(String robot, long step) {
        return step - firstSteps.getOrDefault(robot, 1L) + 1;
    }

    /** @return whether a robot was added to the world since the last call */
    boolean takeWorldChanged() {
        boolean changed = worldChanged;
        worldChanged = false;
        return changed;
    }

    /**
     * Admits or refuses a robot's hello.
     *
     * @param c        the connection it came on
     * @param hello    the hello
     * @param robots   the robots connected, by name, to which an admitted robot is added
     * @param openStep the step open, or 0 between steps
     */
    void hello(Connection c, RobotHello hello, Map<String, Connection> robots, long openStep) {
        boolean started = departures.started() || openStep > 0;
        String refusal = admission.refusal(c, hello, robots.containsKey(hello.name()));
        boolean spawned = refusal == null && !sim().robotNames().contains(hello.name());
        if (spawned) {
            refusal = spawn(hello);
        } else if (refusal == null) {
            refusal = started ? sameBody(hello) : useParameters(hello);
        }
        if (refusal != null) {
            String why = refusal;
            limited.warning("refused robot hellos", () -> "refusing robot "
                    + RobotHello.printable(hello.name()) + ": "
                    + why);
            refusals.refused(RobotHello.printable(hello.name()), refusal);
            if (c.isLink()) {
                c.send(new Bye(Bye.REFUSED + refusal, hello.name()));
            } else {
                c.sendAndClose(new Bye(Bye.REFUSED + refusal));
            }
            return;
        }
        if (c.isLink()) {
            c.addRobot(hello.name());
        } else {
            c.setName(hello.name());
        }
        robots.put(hello.name(), c);
        refusals.admitted(hello.name());
        sim().setConnected(hello.name(), true);
        c.send(new Welcome(hello.name(), sim().world().stepMs(), sim().state(hello.name()), sim().world().properties(),
                sim().seed()));
        long first = openStep > 0 ? openStep + 1 : sim().stepCount() + 1;
        firstSteps.put(hello.name(), first);
        String on = c.isLink() ? " on a shared link (" + c.peer() + ")" : "";
        Join join = departures.joined(hello.name(), spawned, first);
        if (join == null) {
            LOG.info(() -> "robot " + hello.name() + " connected" + on);
        } else {
            LOG.info(() -> "robot " + hello.name() + " " + join.describe() + on + " (after step " + sim().stepCount()
                    + ")");
        }
    }

    /** An open world's newcomer: placed at the first free spawn pose. @return why not, or null */
    private String spawn(RobotHello hello) {
        try {
            String type = hello.robotType().toLowerCase(Locale.ROOT);
            Pose2D at = sim().spawn(hello.name(), type, hello.parameters(), sim().world().rules().spawns());
            worldChanged = true;
            LOG.info(() -> String.format(Locale.ROOT, "robot %s (a %s the world does not name) placed at spawn pose"
                    + " (%.0f, %.0f, %.0f)", hello.name(), type, at.x(), at.y(), Math.toDegrees(at.th())));
            return null;
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
    }

    /** Before the run: the program's parameters become the body's. @return why not, or null */
    private String useParameters(RobotHello hello) {
        try {
            RobotParameters params = keepingGripper(hello.parameters(), sim().world().robots().stream()
                    .anyMatch(r -> r.name().equals(hello.name()) && r.parameters().hasGripper()));
            overriding(hello.name(), params);
            sim().useParameters(hello.name(), params);
            return null;
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
    }

    /** During the run: the program must bring its body's parameters. @return why not, or null */
    private String sameBody(RobotHello hello) {
        RobotParameters body = sim().parameters(hello.name());
        String difference = ParameterDifference.first(body, keepingGripper(hello.parameters(), body.hasGripper()),
                "its body");
        if (difference == null) {
            return null;
        }
        return "robot " + hello.name() + " joins the run under way (after step " + sim().stepCount()
                + ") with parameters that differ from its body's (first: " + difference
                + "); a body keeps its parameters during a run";
    }

    /** Says in one line when a robot program's parameters differ from its world file's, and that the program's win. */
    private void overriding(String name, RobotParameters params) {
        sim().world().robots().stream().filter(r -> r.name().equals(name)).findFirst().ifPresent(spec -> {
            String difference = ParameterDifference.first(spec.parameters(), params);
            if (difference != null) {
                String file = spec.parameterFile() == null ? "" : " " + spec.parameterFile().getFileName();
                LOG.info(() -> "robot " + name + ": its program's parameters differ from the world's file"
                        + file + " (first: " + difference + "); the program's parameters win");
            }
        });
    }

    /**
     * A gripper is the body's hardware, as on a Pioneer: an ARIA program learns of it by asking the
     * robot (ArGripper.cpp's type query), not from its parameter file, so a body the world fits with
     * a gripper keeps it whatever its program's parameters say.
     *
     * @param params  the program's parameters
     * @param gripper whether the body has a gripper
     * @return the parameters, with the gripper if the body has one
     */
    private static RobotParameters keepingGripper(RobotParameters params, boolean gripper) {
        return gripper && !params.hasGripper() ? params.withGripper(true) : params;
    }
}
