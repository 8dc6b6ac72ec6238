package robosim.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunProgress;
import robosim.protocol.RunSecret;

/**
 * Shows an Environment's progress on a {@link StatusLine}: while it waits for robots, which ones and
 * how long of how long ({@code waiting for robot r3 (2 of 3 connected) - 12 s of 600}); while it
 * runs, the step, steps per second, how many times faster than real time, the robots connected and,
 * when the run has a step limit, a bar and the time left ({@code ETA}); while a step waits for late
 * robots, which ones. On a terminal the line is redrawn a few times a second; anywhere else a plain
 * line comes every {@link #PLAIN_EVERY_S} s while running (and at each tenth of a step limit, at most one a second),
 * and while waiting as {@link WaitSchedule} says.
 */
final class RunProgressLine implements RunProgress, AutoCloseable {
    /** How often the server tells where the run is, ms. */
    static final long INTERVAL_MS = 250;
    /** Seconds between two plain lines while running. */
    static final long PLAIN_EVERY_S = 10;
    /** A step held up for less than this is still running, ns. */
    static final long HELD_AFTER_NANOS = TimeUnit.SECONDS.toNanos(1);
    private static final long RATE_WINDOW_NANOS = TimeUnit.SECONDS.toNanos(2);
    private static final int BAR = 10;
    private static final int NAMES_SHOWN = 6;

    private final StatusLine line;
    private final LongSupplier clock;
    private final long plainEveryNanos;
    private final String etaLabel;
    private final WaitSchedule waits = new WaitSchedule();
    private Phase waitPhase;
    private Set<String> refusedShown = Set.of();
    private long waitStep = -1;
    private long lastLineNanos;
    private boolean anyLine;
    private long lastTenth;
    private long refRunNanos;
    private long refStep;
    private long refTimeMs;
    private double stepsPerS = Double.NaN;
    private double realTimes = Double.NaN;

    /**
     * @param line            where to show it
     * @param clock           the time, ns (as {@link System#nanoTime()})
     * @param plainEveryNanos time between two plain lines while running
     * @param limitIsCap      whether the step limit is only a cap (the run is expected to end before it, as
     *                        GoldFinder's does when the gold is found): the time left to it is then
     *                        {@code limit in}, not {@code ETA}
     */
    RunProgressLine(StatusLine line, LongSupplier clock, long plainEveryNanos, boolean limitIsCap) {
        this.line = line;
        this.clock = clock;
        this.plainEveryNanos = plainEveryNanos;
        this.etaLabel = limitIsCap ? "limit in " : "ETA ";
    }

    /**
     * Has a server's run shown on standard error, unless {@code quiet}.
     *
     * @param server     the server, before its run
     * @param err        the command's standard error
     * @param quiet      whether to show nothing
     * @param limitIsCap whether the step limit is only a cap, which the run is expected to end before
     * @return the progress line to close when the run has ended (it clears a terminal's line), or null if quiet
     */
    static RunProgressLine follow(EnvironmentServer server, PrintWriter err, boolean quiet, boolean limitIsCap) {
        if (quiet) {
            return null;
        }
        RunProgressLine p = new RunProgressLine(StatusLine.on(err), System::nanoTime,
                TimeUnit.SECONDS.toNanos(PLAIN_EVERY_S), limitIsCap);
        server.setProgress(p, INTERVAL_MS);
        return p;
    }

    @Override
    public void progress(Status s) {
        long now = clock.getAsLong();
        if (s.phase() == Phase.CONNECTING || s.phase() == Phase.STEP_HELD && s.waitedNanos() >= HELD_AFTER_NANOS) {
            waiting(s);
        } else {
            running(s, now);
        }
    }

    private void waiting(Status s) {
        if (s.phase() != waitPhase || s.step() != waitStep) {
            waitPhase = s.phase();
            waitStep = s.step();
            waits.reset();
        }
        // a new refusal is news: shown at once, not at the next line the schedule allows
        boolean newRefusal = !s.refused().keySet().equals(refusedShown);
        refusedShown = s.refused().keySet();
        if (line.isTerminal() || waits.due(s.waitedNanos()) || newRefusal && !s.refused().isEmpty()) {
            line.show(describeWait(s));
        }
    }

    private void running(Status s, long now) {
        waitPhase = null;
        rates(s);
        if (line.isTerminal()) {
            line.show(terminalRunning(s));
            return;
        }
        long tenth = s.maxSteps() > 0 ? s.step() * 10 / s.maxSteps() : 0;
        long since = now - lastLineNanos;
        boolean due = !anyLine ? s.runNanos() >= plainEveryNanos : since >= plainEveryNanos;
        boolean newTenth = tenth > lastTenth && (!anyLine || since >= TimeUnit.SECONDS.toNanos(1));
        if (due || newTenth) {
            line.show(plainRunning(s));
            lastLineNanos = now;
            anyLine = true;
            lastTenth = tenth;
        }
    }

    /**
     * Steps per second and times real time over the last {@link #RATE_WINDOW_NANOS} or so; until
     * the first such window has passed, over the run so far.
     */
    private void rates(Status s) {
        long dt = s.runNanos() - refRunNanos;
        if (dt >= RATE_WINDOW_NANOS) {
            stepsPerS = (s.step() - refStep) * 1e9 / dt;
            realTimes = (s.timeMs() - refTimeMs) * 1e6 / dt;
            refRunNanos = s.runNanos();
            refStep = s.step();
            refTimeMs = s.timeMs();
        } else if (refRunNanos == 0 && s.step() > 0 && s.runNanos() > 0) {
            stepsPerS = s.step() * 1e9 / s.runNanos();
            realTimes = s.timeMs() * 1e6 / s.runNanos();
        }
    }

    /** For example {@code [###-------]  35% step 7000/20000  2345/s  23.4x real time  3 robots  ETA 0:06}. */
    private String terminalRunning(Status s) {
        StringBuilder b = new StringBuilder();
        if (s.maxSteps() > 0) {
            int filled = (int) Math.min(BAR, s.step() * BAR / s.maxSteps());
            b.append('[').append("#".repeat(filled)).append("-".repeat(BAR - filled)).append("] ");
            b.append(String.format(Locale.ROOT, "%3d%% step %d/%d  %s/s", s.step() * 100 / s.maxSteps(), s.step(),
                    s.maxSteps(), stepsPerSecond()));
        } else {
            b.append("step ").append(s.step()).append("  ").append(stepsPerSecond()).append(" steps/s");
        }
        b.append("  ").append(realTime()).append("x real time  ").append(robots(s, null));
        b.append("  ").append(eta(s) != null ? etaLabel + eta(s) : duration(s.runNanos()));
        return b.toString();
    }

    /** For example {@code step 7000 of 20000 (35%), 2345 steps/s, 23.4x real time, 3 robots, 0:03 elapsed, ETA 0:06}. */
    private String plainRunning(Status s) {
        StringBuilder b = new StringBuilder("step ").append(s.step());
        if (s.maxSteps() > 0) {
            b.append(" of ").append(s.maxSteps()).append(" (").append(s.step() * 100 / s.maxSteps()).append("%)");
        }
        b.append(", ").append(stepsPerSecond()).append(" steps/s, ").append(realTime()).append("x real time, ")
                .append(robots(s, ", ")).append(", ").append(duration(s.runNanos())).append(" elapsed");
        String eta = eta(s);
        if (eta != null) {
            b.append(", ").append(etaLabel).append(eta);
        }
        return b.toString();
    }

    /** @return the robots connected, and after {@code sep} the viewers if any (none if {@code sep} is null) */
    private static String robots(Status s, String sep) {
        String robots = s.connected() == s.robots() ? plural(s.robots(), "robot")
                : s.connected() + " of " + s.robots() + " robots";
        return s.viewers() > 0 && sep != null ? robots + sep + plural(s.viewers(), "viewer") : robots;
    }

    /** @return the time left until the step limit at the run's average pace (steadier than the last seconds'), or null */
    private static String eta(Status s) {
        if (s.maxSteps() <= 0 || s.runNanos() <= 0 || s.step() <= 0) {
            return null;
        }
        return duration((long) ((s.maxSteps() - s.step()) * (double) s.runNanos() / s.step()));
    }

    private String stepsPerSecond() {
        if (Double.isNaN(stepsPerS)) {
            return "-";
        }
        return stepsPerS >= 10_000 ? String.format(Locale.ROOT, "%.1fk", stepsPerS / 1000)
                : String.format(Locale.ROOT, "%.0f", stepsPerS);
    }

    private String realTime() {
        if (Double.isNaN(realTimes)) {
            return "-";
        }
        return String.format(Locale.ROOT, realTimes >= 100 ? "%.0f" : "%.1f", realTimes);
    }

    /** @return what a waiting Environment waits for, how long it has waited, and how long it will */
    static String describeWait(Status s) {
        // a wait with no limit (robots after a restart or load) says so rather than "of 0"
        String of = " - " + WaitSchedule.seconds(s.waitedNanos()) + " s"
                + (s.waitLimitNanos() > 0 ? " of " + limit(s.waitLimitNanos()) : ", no time limit");
        if (s.phase() == Phase.STEP_HELD) {
            List<String> late = s.waitingFor();
            String whose = late.size() == 1 ? "robot " + late.get(0) + "'s requests"
                    : "the requests of robots " + names(late);
            return "step " + (s.step() + 1) + " waits for " + whose + of;
        }
        StringBuilder b = new StringBuilder("waiting for ");
        List<String> missing = s.waitingFor();
        if (!missing.isEmpty()) {
            b.append(missing.size() == 1 ? "robot " : "robots ").append(names(missing))
                    .append(" (").append(s.connected()).append(" of ").append(s.robots()).append(" connected)");
        }
        int viewers = Math.max(0, s.viewersAwaited() - s.viewers());
        if (viewers > 0) {
            b.append(missing.isEmpty() ? "" : " and ").append(plural(viewers, "viewer"));
        }
        b.append(of);
        if (!s.refused().isEmpty()) {
            b.append("; refused: ").append(refusals(s.refused()));
            // a shared link's robots are unnamed until it is admitted: a refused link may hold any of them
            boolean linkRefused = s.refused().keySet().stream().anyMatch(who -> who.startsWith("a shared link"));
            if (!missing.isEmpty() && s.refused().keySet().containsAll(missing)) {
                b.append(". Every robot waited for was refused: ").append(advice(s.refused()));
            } else if (linkRefused) {
                b.append(". The robots of a refused shared link are not named here: ").append(advice(s.refused()));
            }
        }
        return b.toString();
    }

    /** @return {@code r1 (presented no run secret), r2 (...)}, the latest {@link #NAMES_SHOWN} */
    private static String refusals(Map<String, String> refused) {
        List<String> shown = new ArrayList<>();
        refused.forEach((who, why) -> shown.add(who + " (" + why + ")"));
        int from = Math.max(0, shown.size() - NAMES_SHOWN);
        return (from > 0 ? from + " more and " : "") + String.join(", ", shown.subList(from, shown.size()));
    }

    /** @return what to do when every robot waited for was refused */
    static String advice(Map<String, String> refused) {
        boolean secret = refused.values().stream().anyMatch(RunSecret::isSecretRefusal);
        return secret ? "start them on this machine as the same user (they read the secret file this Environment"
                + " wrote), or give them the secret it printed (ROBOSIM_TOKEN or -Drobosim.token); see docs/SECURITY.md"
                : "fix what the refusals say and start them again; the Environment keeps waiting";
    }

    private static String names(List<String> names) {
        if (names.size() <= NAMES_SHOWN) {
            return String.join(", ", names);
        }
        return String.join(", ", names.subList(0, NAMES_SHOWN)) + " and " + (names.size() - NAMES_SHOWN) + " more";
    }

    private static String limit(long nanos) {
        long ms = TimeUnit.NANOSECONDS.toMillis(nanos);
        return ms % 1000 == 0 ? Long.toString(ms / 1000) : String.format(Locale.ROOT, "%.1f", ms / 1000.0);
    }

    private static String plural(long n, String what) {
        return n + " " + what + (n == 1 ? "" : "s");
    }

    /** @return {@code m:ss}, or {@code h:mm:ss} from an hour */
    static String duration(long nanos) {
        long s = TimeUnit.NANOSECONDS.toSeconds(Math.max(0, nanos));
        return s >= 3600 ? String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60)
                : String.format(Locale.ROOT, "%d:%02d", s / 60, s % 60);
    }

    /** Clears a terminal's line, so that the results print on a clean one. */
    @Override
    public void close() {
        line.close();
    }
}
