package robosim.env.net;

import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import robosim.env.world.World;
import robosim.env.world.xml.WorldFileException;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.LogLimiter;

/**
 * Reads the world a control client's {@code load} names, in the Environment's process, before
 * anything in the run changes. The Environment reads only world files under the directory of the
 * world it was started with (symbolic links followed, so none leads out of it): a control client
 * presents the run's secret, but should not make the Environment read whatever its user may. A
 * broken world is refused with the reader's error, naming the file and line.
 */
final class WorldLoader {
    private final CurrentRun run;
    private final int maxRobots;

    WorldLoader(CurrentRun run, int maxRobots) {
        this.run = run;
        this.maxRobots = maxRobots;
    }

    /**
     * @param text the path the client sent, relative to the directory of the Environment's world
     * @return the world, read and checked
     * @throws IllegalArgumentException naming the path and the rule it breaks, or the reader's error
     */
    World read(String text) {
        Path dir = run.worldDirectory();
        if (dir == null) {
            throw new IllegalArgumentException("load: this Environment was not started from a world file, so it has"
                    + " no directory to load worlds from");
        }
        Path file;
        try {
            file = dir.resolve(text).normalize();
        } catch (InvalidPathException e) {
            throw new IllegalArgumentException("load: '" + LogLimiter.excerpt(text) + "' is not a path");
        }
        // checked before the file is looked at, so that no client learns what exists outside
        if (!file.startsWith(dir)) {
            throw outside(text, dir);
        }
        Path real;
        try {
            real = file.toRealPath();
        } catch (IOException e) {
            throw new IllegalArgumentException("load: no world file " + LogLimiter.excerpt(text) + " in " + dir);
        }
        if (!real.startsWith(realDirectory(dir))) {
            throw outside(text, dir);
        }
        World w;
        try {
            w = WorldReader.read(real);
        } catch (WorldFileException e) {
            throw new IllegalArgumentException("load: " + e.getMessage());
        }
        if (w.robots().size() > maxRobots) {
            throw new IllegalArgumentException("load: world " + w.name() + " names " + w.robots().size()
                    + " robots, more than this Environment admits (" + maxRobots + ", --max-robots)");
        }
        return w;
    }

    private static IllegalArgumentException outside(String text, Path dir) {
        return new IllegalArgumentException("load: " + LogLimiter.excerpt(text) + " is outside " + dir
                + ", the directory of the world this Environment was started with; load reads world files there only");
    }

    private static Path realDirectory(Path dir) {
        try {
            return dir.toRealPath();
        } catch (IOException e) {
            return dir;
        }
    }
}
