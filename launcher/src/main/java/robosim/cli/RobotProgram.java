package robosim.cli;

import java.io.PrintWriter;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import robosim.hw.RunEnd;
import robosim.hw.RunEndWatch;

/**
 * Runs a robot program's {@code main} and reports how its robots' parts in the run ended, one line
 * each, with the exit code {@code robosim robot} gives for them. The program's {@code main} runs on
 * a thread of its own, so that the launcher can end the program once every robot is out of the run
 * even if {@code main} never returns (a loop that waits for a move the Environment will never
 * finish): it waits for {@code main} to return, then for robots kept in the run after it
 * ({@code runAsync}); and once all the program's robots are out of the run by the Environment's
 * doing, it gives {@code main} {@link #GRACE_MS} to return by itself.
 */
final class RobotProgram {
    /** The exit code when the Environment was lost: it closed the connection, it died or it went silent. */
    static final int LOST = 3;
    /** The exit code when the Environment refused or dropped a robot. */
    static final int REFUSED_OR_DROPPED = 4;
    /** How long {@code main} may go on once every robot of the program is out of the run, ms. */
    static final long GRACE_MS = 2_000;
    private static final long POLL_MS = 50;

    private final Method main;
    private final String[] args;
    private final ClassLoader loader;
    private final String name;
    private final boolean quiet;
    private final Map<String, WaitSchedule> waits = new HashMap<>();
    private volatile Throwable failure;

    /**
     * @param main   the program's {@code public static void main(String[])}
     * @param args   its arguments
     * @param loader where its classes come from
     * @param name   the robot's name, for messages
     * @param quiet  whether to keep quiet while the program's robots wait for the Environment
     */
    RobotProgram(Method main, String[] args, ClassLoader loader, String name, boolean quiet) {
        this.main = main;
        this.args = args;
        this.loader = loader;
        this.name = name;
        this.quiet = quiet;
    }

    /**
     * Runs the program until it and its robots are done, then prints a line for each robot's end
     * (the run's end or the program's own leave on {@code out}, anything else on {@code err}), and
     * the program's failure with its stack trace. Meanwhile, unless quiet, says on {@code err} every few
     * seconds what a robot that has had no step yet waits for: the Environment's answer, or the
     * first step (the Environment begins once every robot of its world has connected).
     *
     * @return 0 if every robot ran to the end of the run or left it, {@link #LOST},
     *         {@link #REFUSED_OR_DROPPED}, or 1 if a robot could not connect or {@code main} threw
     * @throws InterruptedException if interrupted while waiting
     */
    int run(PrintWriter out, PrintWriter err) throws InterruptedException {
        try (RunEndWatch watch = RunEndWatch.open()) {
            Thread program = new Thread(this::invoke, "robot-program-" + name);
            program.setContextClassLoader(loader);
            program.start();
            awaitProgram(program, watch, err);
            while (!watch.awaitNoneRunning(POLL_MS * 4)) {
                // robots kept in the run after main returned; each ends with the run, or lost
                sayWhatRobotsWaitFor(watch, err);
            }
            return report(watch.ends(), out, err);
        }
    }

    /**
     * Says, as {@link WaitSchedule} has it, what the robots that have had no step yet wait for: one
     * line for those still waiting for the Environment's answer, one for those waiting for step 1
     * (per Environment), however many robots the program has.
     */
    private void sayWhatRobotsWaitFor(RunEndWatch watch, PrintWriter err) {
        if (quiet) {
            return;
        }
        Map<String, List<RunEndWatch.BeforeFirstStep>> byState = new TreeMap<>();
        for (RunEndWatch.BeforeFirstStep w : watch.beforeFirstStep()) {
            byState.computeIfAbsent((w.welcomed() ? w.afterStep() > 0 ? "joined " : "welcomed " : "connecting ") + w.environment(),
                    k -> new ArrayList<>()).add(w);
        }
        for (Map.Entry<String, List<RunEndWatch.BeforeFirstStep>> state : byState.entrySet()) {
            List<RunEndWatch.BeforeFirstStep> robots = state.getValue();
            long waited = robots.stream().mapToLong(RunEndWatch.BeforeFirstStep::waitedNanos).max().orElse(0);
            if (waits.computeIfAbsent(state.getKey(), k -> new WaitSchedule()).due(waited)) {
                err.println(describe(robots, waited));
                err.flush();
            }
        }
        waits.keySet().retainAll(byState.keySet());
    }

    /**
     * @param robots robots in the same state, before their first step, of one Environment
     * @param waited how long the first of them has waited, ns
     * @return what they wait for, and for how long
     */
    static String describe(List<RunEndWatch.BeforeFirstStep> robots, long waited) {
        List<String> names = robots.stream().map(RunEndWatch.BeforeFirstStep::robot).sorted().toList();
        String who = names.size() == 1 ? "robot " + names.get(0) + " is"
                : "robots " + (names.size() <= 6 ? String.join(", ", names)
                        : String.join(", ", names.subList(0, 6)) + " and " + (names.size() - 6) + " more") + " are";
        RunEndWatch.BeforeFirstStep first = robots.get(0);
        String time = " - " + WaitSchedule.seconds(waited) + " s";
        if (!first.welcomed()) {
            return "robosim robot: " + who + " waiting for the Environment at " + first.environment()
                    + " to answer (it keeps trying while nothing listens there)" + time;
        }
        if (first.afterStep() > 0) {
            return "robosim robot: " + who + " in the run at " + first.environment() + " since step "
                    + first.afterStep() + ", waiting for the next step (the run may be paused)" + time;
        }
        return "robosim robot: " + who + " connected to the Environment at " + first.environment()
                + ", waiting for step 1: the run starts once every robot of the world has connected" + time;
    }

    private void invoke() {
        try {
            main.invoke(null, (Object) args);
        } catch (InvocationTargetException e) {
            failure = e.getCause();
        } catch (IllegalAccessException | RuntimeException e) {
            failure = e;
        }
    }

    /** Waits until main returns, or until the Environment has ended every robot and main had its grace. */
    private void awaitProgram(Thread program, RunEndWatch watch, PrintWriter err) throws InterruptedException {
        while (program.isAlive()) {
            program.join(POLL_MS);
            sayWhatRobotsWaitFor(watch, err);
            if (program.isAlive() && watch.running() == 0 && endedByEnvironment(watch.ends())) {
                program.join(GRACE_MS);
                if (watch.running() == 0) {
                    return;
                }
            }
        }
    }

    private static boolean endedByEnvironment(List<RunEnd> ends) {
        return ends.stream().anyMatch(e -> e.kind() != RunEnd.Kind.LEFT && e.kind() != RunEnd.Kind.NOT_CONNECTED);
    }

    private int report(List<RunEnd> ends, PrintWriter out, PrintWriter err) {
        Map<String, RunEnd> last = new LinkedHashMap<>();
        for (RunEnd e : ends) {
            last.put(e.robot(), e);
        }
        for (RunEnd e : ends) {
            // a robot that could not connect: its program's connect call said why, and the log too;
            // a refusal followed by another end was tried again (a secret found before the
            // Environment wrote its own), and what came of that is said instead
            if (e.kind() == RunEnd.Kind.NOT_CONNECTED || e.kind() == RunEnd.Kind.REFUSED && last.get(e.robot()) != e) {
                continue;
            }
            if (e.kind().isFailure()) {
                err.println("robosim robot: " + e.describe());
            } else {
                out.println(e.describe());
            }
        }
        if (failure != null && !toldAlready(failure, ends)) {
            out.flush();
            err.println("robosim robot: robot " + name + "'s program failed:");
            ProgramTrace.print(failure, err);
        }
        out.flush();
        err.flush();
        for (RunEnd e : ends) {
            if (last.get(e.robot()) == e && e.kind().isFailure()) {
                return exitCode(e.kind());
            }
        }
        return failure != null ? 1 : 0;
    }

    /** @return whether the program failed only by passing on why its robot could not connect, which the log told */
    private static boolean toldAlready(Throwable failure, List<RunEnd> ends) {
        String message = String.valueOf(failure.getMessage());
        return ends.stream().anyMatch(e -> e.kind() == RunEnd.Kind.NOT_CONNECTED && e.reason() != null
                && message.contains(e.reason()));
    }

    /** @return the exit code for a robot's part that ended this way */
    static int exitCode(RunEnd.Kind kind) {
        return switch (kind) {
            case RUN_ENDED, LEFT -> 0;
            case NOT_CONNECTED -> 1;
            case LOST -> LOST;
            case REFUSED, DROPPED -> REFUSED_OR_DROPPED;
        };
    }
}
