package robosim.aria;

import java.util.function.BooleanSupplier;

/**
 * What {@link ArRobot} keeps of its connection besides the link itself, as ARIA's {@code ArRobot}
 * keeps it (ArRobot.cpp): the callback lists, the stabilizing period, the connection's times and
 * why it was dropped, and the conditions threads wait on ({@code waitForConnect} and its kin, woken
 * by the {@code wakeAll...} calls). Times are simulated ms.
 */
final class ConnectionEvents {
    final Callbacks connect = new Callbacks("addConnectCB");
    final Callbacks failedConnect = new Callbacks("addFailedConnectCB");
    final Callbacks disconnectNormally = new Callbacks("addDisconnectNormallyCB");
    final Callbacks disconnectOnError = new Callbacks("addDisconnectOnErrorCB");
    final Callbacks runExit = new Callbacks("addRunExitCB");
    final Callbacks stabilizing = new Callbacks("addStabilizingCB");
    final Callbacks setEncoderTransform = new Callbacks("addSetEncoderTransformCB");

    /** ARIA's default connection timeout, ms. */
    static final int DEFAULT_TIMEOUT_MS = 8000;

    volatile boolean isStabilizing;
    volatile long stabilizingStartMs;
    volatile int stabilizingTimeMs;
    volatile long openedMs;
    volatile int timeoutMs = DEFAULT_TIMEOUT_MS;
    volatile String dropReason = "";
    volatile String dropUserReason = "";

    /** Whether the robot finished connecting and its end has not yet been told. */
    private boolean live;
    /** Bumped by a connect, a failed connect, the run's exit and the wake calls: what waiters watch. */
    private long connEvents;
    private long connOrFailEvents;
    private long runExitEvents;

    /** The connection finished: from now on its end is told once. */
    synchronized void connected() {
        live = true;
        connEvents++;
        connOrFailEvents++;
        notifyAll();
    }

    synchronized void failed() {
        connOrFailEvents++;
        notifyAll();
    }

    /** @return whether the connection has finished and its end has not been told */
    synchronized boolean isLive() {
        return live;
    }

    /** @return whether the connection's end is to be told now (true once per connection) */
    synchronized boolean claimEnd() {
        boolean was = live;
        live = false;
        return was;
    }

    synchronized long runExitEvents() {
        return runExitEvents;
    }

    synchronized void runExited() {
        runExitEvents++;
        notifyAll();
    }

    synchronized void wakeConn() {
        connEvents++;
        notifyAll();
    }

    synchronized void wakeConnOrFail() {
        connOrFailEvents++;
        notifyAll();
    }

    synchronized void wakeRunExit() {
        runExitEvents++;
        notifyAll();
    }

    /** The three kinds of wait. */
    enum Kind { CONN, CONN_OR_FAIL, RUN_EXIT }

    private long events(Kind k) {
        return switch (k) {
            case CONN -> connEvents;
            case CONN_OR_FAIL -> connOrFailEvents;
            case RUN_EXIT -> runExitEvents;
        };
    }

    /**
     * Waits, in wall-clock time, until {@code done} holds or an event of the kind comes.
     *
     * @param ms at most this long; 0 for no limit
     * @return 0 when done or woken, 1 when the time ran out, 2 when interrupted
     */
    synchronized int await(Kind kind, BooleanSupplier done, long ms) {
        long start = events(kind);
        long deadline = System.nanoTime() + ms * 1_000_000L;
        try {
            while (!done.getAsBoolean() && events(kind) == start) {
                if (ms == 0) {
                    wait(100);
                } else {
                    long left = (deadline - System.nanoTime()) / 1_000_000L;
                    if (left <= 0) {
                        return 1;
                    }
                    wait(Math.min(left, 100));
                }
            }
            return 0;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 2;
        }
    }
}
