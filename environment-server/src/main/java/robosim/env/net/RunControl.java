package robosim.env.net;

import java.util.ArrayDeque;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import robosim.env.core.Simulation;
import robosim.env.world.World;
import robosim.protocol.ControlReply;
import robosim.protocol.ControlRequest;
import robosim.protocol.LogLimiter;

/**
 * Run control, owned by the {@link EnvironmentServer}, which hands it a narrow view of the sessions ({@link RunSessions}): the control clients' pause, resume, step N, stop, pace,
 * move, remove, restart and load (the step loop starts the new run, see {@link #takeSwitch()}). A request whose values break a rule is refused at once and changes nothing; the
 * others wait for the next step boundary (after the step under way, before the next is opened) and
 * are carried out there in the order they came, so that the same requests at the same steps give the
 * same run. Each is answered with a {@link ControlReply}; a client that has gone meanwhile is not
 * answered, but what it asked for is still done.
 *
 * <p>While paused no step is opened, so no robot's step deadline runs; the step loop keeps the robots
 * connected with keep-alives. {@code step N} runs N steps and pauses again, answering once they are run.
 */
final class RunControl implements ControlRequests {
    private static final Logger LOG = Logger.getLogger(SessionRules.class.getName());
    /** The most requests waiting for a step boundary, all clients together. */
    static final int MAX_PENDING = 64;
    /** The request that has the Environment's log lines sent to the client ({@link LogForwarding}). */
    static final String LOG_OP = "log";

    /** A request checked and waiting for the step boundary. */
    private record Pending(Connection from, long id, ControlOp op) { }

    /**
     * A new run asked for by {@code restart} or {@code load}, for the step loop to start.
     *
     * @param world the world to run
     * @param why   what the robots of the run ending are told, and the log says
     * @param from  the client that asked, answered once the new run is in place
     * @param id    its request's id
     */
    record Switch(World world, String why, Connection from, long id) {
        /** Tells the client that asked what became of it. */
        void answer(String text) {
            from.send(new ControlReply(id, true, text));
        }
    }

    private final CurrentRun run;
    private final RunSessions sessions;
    private final WorldLoader loader;
    private final LogLimiter limited;
    private final ArrayDeque<Pending> pending = new ArrayDeque<>();
    private Switch switchTo;
    private boolean paused;
    private long stepsLeft;
    private Pending stepping;
    /** 0 for as fast as possible, else a factor of real time. */
    private double pace;
    private boolean rebase = true;
    private long baseNanos;
    private long baseStep;

    /**
     * @param run       the run it controls
     * @param sessions  what it may see and do of the run's sessions
     * @param maxRobots the most robots a world it loads may name
     * @param limited   the limiter of the lines clients can repeat
     */
    RunControl(CurrentRun run, RunSessions sessions, int maxRobots, LogLimiter limited) {
        this.limited = limited;
        this.run = run;
        this.sessions = sessions;
        this.loader = new WorldLoader(run, maxRobots);
    }

    private Simulation sim() {
        return run.sim();
    }

    /** @param factor the pace the run starts with: 0 for as fast as possible, 1 for real time */
    void startPace(double factor) {
        pace = factor;
    }

    /** A control client sent a request: refused now if a value breaks a rule, else kept for the step boundary. */
    @Override
    public void received(Connection c, ControlRequest r) {
        if (StatusReport.OP.equals(r.op())) {
            // a status changes nothing, so it need not wait for a step boundary
            c.send(StatusReport.answer(r, sim(), sessions, paused, pace));
            return;
        }
        if (LOG_OP.equals(r.op())) {
            // following the log changes nothing in the run either
            if (!r.args().isEmpty()) {
                refuse(c, r.id(), "log takes 0 arguments (log), got " + r.args().size());
                return;
            }
            sessions.log().follow(c);
            c.send(new ControlReply(r.id(), true, "following the Environment's log from step " + sim().stepCount()));
            return;
        }
        ControlOp op;
        try {
            op = ControlOp.parse(r, sim());
            if (op instanceof ControlOp.Load l) {
                // read now, so that a broken world is refused at once and the run goes on unharmed
                op = new ControlOp.Load(l.path(), loader.read(l.path()));
            }
        } catch (IllegalArgumentException e) {
            refuse(c, r.id(), e.getMessage());
            return;
        }
        if (pending.size() >= MAX_PENDING) {
            refuse(c, r.id(), MAX_PENDING + " control requests already wait for the end of the step under way");
            return;
        }
        pending.add(new Pending(c, r.id(), op));
    }

    /**
     * Between two steps: carries out the waiting requests in the order they came.
     *
     * @return the run's end ({@link RunEnding#STOPPED}), if a client stopped it; else null
     */
    EndOfRun atBoundary() {
        while (!pending.isEmpty() && switchTo == null) {
            EndOfRun end = apply(pending.poll());
            if (end != null) {
                return end;
            }
        }
        return null;
    }

    /**
     * @return the new run a {@code restart} or {@code load} asked for at this boundary, or null; the
     *         requests that came after it are refused, as they were meant for the run that ends
     */
    Switch takeSwitch() {
        Switch s = switchTo;
        switchTo = null;
        if (s != null) {
            while (!pending.isEmpty()) {
                Pending p = pending.poll();
                reply(p, false, "not carried out: a restart or load before it ended the run it was meant for");
            }
            if (stepping != null) {
                reply(stepping, true, "ended by the " + s.why() + " with " + stepsLeft + " of the steps still to run");
                stepping = null;
                stepsLeft = 0;
            }
            rebase = true;
        }
        return s;
    }

    /** @return whether the loop must not open a step now: paused, and no {@code step N} under way */
    boolean holding() {
        return paused && stepsLeft == 0;
    }

    /**
     * @param current the step about to be opened
     * @param stepMs  the world's step length
     * @param now     the time now, ns
     * @return when the step may be opened at the pace in force (counted from the last change of pace
     *         or resume, so that a pause is not made up for by a burst), ns; now when there is no pace
     */
    long due(long current, int stepMs, long now) {
        if (pace == 0) {
            return now;
        }
        if (rebase) {
            rebase = false;
            baseNanos = now;
            baseStep = current - 1;
        }
        return baseNanos + (long) ((current - 1 - baseStep) * (double) TimeUnit.MILLISECONDS.toNanos(stepMs) / pace);
    }

    /** A step has been run: counts down a {@code step N}, answering it when its steps are done. */
    void stepped() {
        if (stepsLeft > 0 && --stepsLeft == 0) {
            ControlOp.Step s = (ControlOp.Step) stepping.op();
            reply(stepping, true, "ran " + s.steps() + " step" + (s.steps() == 1 ? "" : "s") + "; paused after step "
                    + sim().stepCount());
            stepping = null;
        }
    }

    private EndOfRun apply(Pending p) {
        long k = sim().stepCount();
        String who = "control client " + LogLimiter.excerpt(p.from().name());
        ControlOp op = p.op();
        if (op instanceof ControlOp.Pause) {
            reply(p, true, paused ? "already paused at step " + k : "paused after step " + k);
            paused = true;
        } else if (op instanceof ControlOp.Resume) {
            if (stepping != null) {
                reply(stepping, true, "resumed by " + who + " after step " + k + " with "
                        + stepsLeft + " of the steps still to run");
                stepping = null;
                stepsLeft = 0;
            }
            reply(p, true, paused ? "resumed after step " + k : "already running (step " + k + ")");
            paused = false;
            rebase = true;
        } else if (op instanceof ControlOp.Step s) {
            if (!paused) {
                reply(p, false, "step N runs steps while the run is paused; it runs (step " + k + "): pause it first");
            } else if (stepping != null) {
                reply(p, false, "a step N is under way: " + stepsLeft + " steps still to run");
            } else {
                stepping = p;
                stepsLeft = s.steps();
                rebase = true;
            }
        } else if (op instanceof ControlOp.Stop) {
            reply(p, true, "stopped after step " + k);
            LOG.info(() -> who + " stopped the run after step " + k);
            return new EndOfRun(RunEnding.STOPPED, "stopped by " + who);
        } else if (op instanceof ControlOp.Pace pc) {
            pace = pc.factor();
            rebase = true;
            reply(p, true, "pace " + describe(pace) + " from step " + (k + 1));
        } else if (op instanceof ControlOp.Move m) {
            move(p, m, k);
        } else if (op instanceof ControlOp.Remove r) {
            remove(p, r, who, k);
        } else if (op instanceof ControlOp.Restart) {
            switchTo = new Switch(sim().world(), "restart by " + who + " after step " + k, p.from(), p.id());
        } else if (op instanceof ControlOp.Load l) {
            switchTo = new Switch(l.world(), "load of world " + l.world().name() + " by " + who + " after step " + k,
                    p.from(), p.id());
        }
        return null;
    }

    private void move(Pending p, ControlOp.Move m, long k) {
        String refusal = sim().place(m.robot(), m.x(), m.y(), m.th());
        if (refusal != null) {
            reply(p, false, refusal + " (after step " + k + ")");
            return;
        }
        limited.info("robots moved by control clients", () -> "control client " + LogLimiter.excerpt(p.from().name())
                + " moved robot " + m.robot()
                + " after step " + k);
        reply(p, true, String.format(Locale.ROOT, "robot %s moved to (%.0f, %.0f, %.0f) after step %d", m.robot(),
                m.x(), m.y(), m.th(), k));
    }

    private void remove(Pending p, ControlOp.Remove r, String who, long k) {
        if (!sessions.connectedRobots().containsKey(r.robot())) {
            reply(p, false, "robot " + r.robot() + " is not in the run: its program is not connected");
            return;
        }
        LOG.info(() -> who + " removed robot " + r.robot() + " after step " + k);
        sessions.drop(r.robot(), "removed by " + who + " after step " + k);
        reply(p, true, "robot " + r.robot() + " removed after step " + k + "; it stays where it stopped");
    }

    /** @return the pace as a user gives it */
    static String describe(double pace) {
        if (pace == 0) {
            return "max (as fast as possible)";
        }
        return pace == 1 ? "realtime" : String.format(Locale.ROOT, "%s x real time", pace);
    }

    private static void reply(Pending p, boolean ok, String text) {
        p.from().send(new ControlReply(p.id(), ok, text));
    }

    private void refuse(Connection c, long id, String reason) {
        limited.info("refused control requests", () -> "refusing " + c.peer() + "'s control request: " + reason);
        c.send(new ControlReply(id, false, reason));
    }
}
