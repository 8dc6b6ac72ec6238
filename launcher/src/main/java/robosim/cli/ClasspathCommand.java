package robosim.cli;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import picocli.CommandLine.Command;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.params.RobotParameterFiles;

/**
 * {@code robosim classpath}: prints the absolute classpath of RoboSim's jars, the API modules and
 * the libraries they need, which {@code bin/robosim} builds into {@code launcher/target/lib/}. A
 * robot program kept in a folder of its own compiles and runs against it from there:
 * {@code javac -cp "$(/path/to/robosim/bin/robosim classpath)" -d out MyRobot.java}.
 */
@Command(name = "classpath", mixinStandardHelpOptions = true,
        description = {"Print the absolute classpath of RoboSim's jars (the ARIA and Scout APIs and all they need),"
                + " ':'-separated on one line, for compiling and running a robot program kept in a folder of its own:",
                "  javac -cp \"$(/path/to/robosim/bin/robosim classpath)\" -d out MyRobot.java",
                "  java -cp \"$(/path/to/robosim/bin/robosim classpath):out\" MyRobot r1 localhost 5000"},
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = {"0:printed", "1:the jars are not built (bin/robosim builds them on first use)", "2:bad command line"})
final class ClasspathCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        Path lib = libFolder(RobotParameterFiles.root());
        List<Path> jars = jars(lib);
        if (jars.isEmpty()) {
            spec.commandLine().getErr().println("robosim classpath: no RoboSim jars in " + lib
                    + ": bin/robosim builds them on first use (or run mvn -B package -DskipTests in the clone)");
            return 1;
        }
        spec.commandLine().getOut().println(jars.stream().map(Path::toString)
                .collect(Collectors.joining(File.pathSeparator)));
        return 0;
    }

    /** @return where the build puts RoboSim's jars and their libraries under a RoboSim root */
    static Path libFolder(Path root) {
        return root.resolve("launcher").resolve("target").resolve("lib").toAbsolutePath().normalize();
    }

    /**
     * @param lib a folder of jars
     * @return its jars, absolute and sorted by name (so the classpath is the same on every run), or
     *         none when the folder is missing
     * @throws IOException if the folder cannot be listed
     */
    static List<Path> jars(Path lib) throws IOException {
        if (!Files.isDirectory(lib)) {
            return List.of();
        }
        try (Stream<Path> files = Files.list(lib)) {
            return files.filter(p -> p.getFileName().toString().endsWith(".jar") && Files.isRegularFile(p))
                    .map(p -> p.toAbsolutePath().normalize()).sorted().toList();
        }
    }
}
