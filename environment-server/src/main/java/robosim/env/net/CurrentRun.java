package robosim.env.net;

import java.nio.file.Path;
import robosim.env.core.Simulation;

/**
 * The simulation the Environment runs now, shared by the session rules' parts: a control client's
 * {@code restart} or {@code load} puts a new one in its place between two steps, while the viewers
 * and control clients stay connected.
 */
final class CurrentRun {
    private Simulation sim;
    /** The directory of the world file the Environment was started with, or null: where {@code load} may read. */
    private final Path worldDirectory;

    CurrentRun(Simulation sim) {
        this.sim = sim;
        Path source = sim.world().source();
        this.worldDirectory = source == null || source.toAbsolutePath().getParent() == null ? null
                : source.toAbsolutePath().normalize().getParent();
    }

    /** @return the simulation run now */
    Simulation sim() {
        return sim;
    }

    /** @return the directory of the world file the Environment was started with, or null if it was not started from a file */
    Path worldDirectory() {
        return worldDirectory;
    }

    /** @param next the simulation that replaces the one run now */
    void replace(Simulation next) {
        sim = next;
    }
}
