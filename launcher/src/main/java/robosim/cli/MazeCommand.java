package robosim.cli;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.env.world.maze.Maze;
import robosim.env.world.maze.MazeWorldWriter;
import robosim.env.world.xml.WorldReader;
import robosim.params.RobotParameterFiles;

/** {@code robosim maze}: writes a perfect maze as a world file for GoldFinder. */
@Command(name = "maze", mixinStandardHelpOptions = true,
        description = "Write a perfect maze as a world: walls, the robots' start cells near the lower left, gold in the farthest cell.")
final class MazeCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--cells", arity = "2", required = true, paramLabel = "N", description = "cells across and up, e.g. --cells 10 10")
    int[] cells;

    @Option(names = "--cell-size", defaultValue = "1500", paramLabel = "MM", description = OptionTexts.CELL_SIZE + "; at least 1000; default ${DEFAULT-VALUE}")
    int cellSize;

    @Option(names = "--seed", defaultValue = "1", paramLabel = "SEED", description = OptionTexts.SEED
            + "; the same seed and size give the same maze; default ${DEFAULT-VALUE}")
    long seed;

    @Option(names = "--robots", defaultValue = "8", paramLabel = "N", description = OptionTexts.ROBOTS
            + "; the world's robots r1..rN, in the start cells; default ${DEFAULT-VALUE}")
    int robots;

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "the world file to write (a file: --out names one file in every command)")
    Path out;

    @Override
    public Integer call() throws Exception {
        try {
            Path written = write(cells[0], cells[1], cellSize, seed, robots, out);
            spec.commandLine().getOut().println("Maze: " + cells[0] + " x " + cells[1] + " cells of " + cellSize
                    + " mm, seed " + seed + ", written to " + written.toAbsolutePath());
            return 0;
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
    }

    /** Writes a maze world and reads it back, so a file that breaks a world rule is never left. */
    static Path write(int w, int h, int cellSize, long seed, int robots, Path out) throws java.io.IOException {
        Path params = RobotParameterFiles.resolve("p3dx").toAbsolutePath();
        Path dir = out.toAbsolutePath().getParent();
        String rel = dir.relativize(params).toString().replace('\\', '/');
        String name = "maze-" + w + "x" + h + "-" + seed;
        String xml = MazeWorldWriter.write(Maze.generate(w, h, seed), name, cellSize, robots, rel);
        Files.createDirectories(dir);
        Files.writeString(out, xml, StandardCharsets.UTF_8);
        WorldReader.read(out);
        return out;
    }
}
