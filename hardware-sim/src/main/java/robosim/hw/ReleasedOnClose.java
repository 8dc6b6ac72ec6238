package robosim.hw;

/**
 * What the kinds of link do on closing: close once, and tell the robot's {@link RobotRuntime} that
 * the robot no longer holds a link to its Environment.
 */
abstract class ReleasedOnClose implements EnvironmentLink {
    private final Runnable released;
    private boolean closed;

    /** @param released run once, when the link closes */
    ReleasedOnClose(Runnable released) {
        this.released = released;
    }

    /** @return whether the link has closed */
    final synchronized boolean isClosed() {
        return closed;
    }

    @Override
    public final void close() {
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
        }
        released.run();
        closed();
    }

    /** Lets go of what the link holds; runs once, after the link is marked closed. */
    abstract void closed();
}
