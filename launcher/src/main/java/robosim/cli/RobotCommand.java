package robosim.cli;

import java.io.File;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.URL;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.hw.HardwareOptions;

/**
 * {@code robosim robot}: runs a robot program in this JVM, as the original's
 * {@code java <robotApplication> robotName localhost portNumber}, and says in one line per robot how
 * its part in the run ended, with an exit code for it (see {@link RobotProgram}).
 */
@Command(name = "robot", mixinStandardHelpOptions = true,
        description = {"Run a robot program: CLASS's main(NAME, HOST, PORT, ARGS...).",
                "When the program and its robots are done, prints one line per robot: how its part in the run ended,"
                        + " the Environment's host:port, the last step and the reason."},
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = {"0:the run ended, or the program left it",
                "1:the program failed, or its robot could not connect",
                "2:bad command line",
                "3:the Environment was lost: it closed the connection without a bye, died, or sent nothing for the lost time",
                "4:the Environment refused or dropped the robot"})
final class RobotCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "CLASS", description = "the robot program's class, with a static main(String[])")
    String className;

    @Parameters(index = "1", paramLabel = "NAME", description = "the robot's name in the world")
    String name;

    @Parameters(index = "2", paramLabel = "HOST", description = "the Environment's host")
    String host;

    @Parameters(index = "3", paramLabel = "PORT", description = "the Environment's robot port")
    int port;

    @Parameters(index = "4..*", paramLabel = "ARGS", description = "more arguments for the program")
    List<String> rest = new ArrayList<>();

    @Mixin
    SecretOption secret;

    @Option(names = {"--classpath", "--cp"}, paramLabel = "PATH",
            description = "where the program's classes are, besides RoboSim's (directories or jars, ':'-separated)")
    String classpath;

    @Option(names = "--lost-after", paramLabel = "MS",
            description = "declare the Environment lost after MS ms in which it sent nothing, neither a step nor a keep-alive"
                    + " (it sends one after each second without anything else); default: the system property "
                    + HardwareOptions.LOST_AFTER_PROPERTY + " if set, else " + HardwareOptions.DEFAULT_LOST_AFTER_MS)
    Long lostAfterMs;

    @Mixin
    QuietOption quiet;

    @Override
    public Integer call() throws Exception {
        if (port <= 0 || port > 65535) {
            throw new ParameterException(spec.commandLine(), port + " was supplied for PORT: a port is 1 to 65535");
        }
        String bad = secret.apply();
        if (bad != null) {
            throw new ParameterException(spec.commandLine(), bad);
        }
        if (lostAfterMs != null && (lostAfterMs < 1 || lostAfterMs > Integer.MAX_VALUE)) {
            throw new ParameterException(spec.commandLine(), lostAfterMs + " was supplied for --lost-after: it is 1 to "
                    + Integer.MAX_VALUE + " ms");
        }
        if (lostAfterMs == null) {
            try {
                HardwareOptions.configuredLostAfterMs();
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage());
            }
        }
        ClassLoader loader = getClass().getClassLoader();
        if (classpath != null) {
            List<URL> urls = new ArrayList<>();
            for (String p : classpath.split(File.pathSeparator)) {
                if (p.isEmpty()) {
                    continue;
                }
                if (!new File(p).exists()) {
                    throw new ParameterException(spec.commandLine(),
                            "'" + p + "' was supplied for --classpath: there is no"
                            + " such directory or jar");
                }
                urls.add(new File(p).toURI().toURL());
            }
            loader = new URLClassLoader(urls.toArray(new URL[0]), loader);
        }
        Method main;
        try {
            main = Class.forName(className, true, loader).getMethod("main", String[].class);
        } catch (ClassNotFoundException | NoSuchMethodException e) {
            spec.commandLine().getErr().println("robosim robot: no class " + className
                    + " with a public static main(String[]) on the classpath" + (classpath == null ? " (see --classpath)" : ""));
            return 1;
        } catch (ExceptionInInitializerError e) {
            // the program's own code failed as its class loaded: a static initializer threw
            spec.commandLine().getErr().println("robosim robot: robot " + name + "'s program failed as its class "
                    + className + " was initialized:");
            ProgramTrace.print(e.getCause() != null ? e.getCause() : e, spec.commandLine().getErr());
            return 1;
        } catch (LinkageError e) {
            spec.commandLine().getErr().println("robosim robot: the class " + className + " cannot be loaded: " + e
                    + (e instanceof NoClassDefFoundError ? " (a class it needs is not on the classpath; see --classpath)" : ""));
            return 1;
        }
        if (!Modifier.isStatic(main.getModifiers())) {
            spec.commandLine().getErr().println("robosim robot: " + className + ".main is not static");
            return 1;
        }
        List<String> args = new ArrayList<>(List.of(name, host, Integer.toString(port)));
        args.addAll(rest);
        // the program's robots read the lost time when they connect, without code of their own
        String before = System.getProperty(HardwareOptions.LOST_AFTER_PROPERTY);
        if (lostAfterMs != null) {
            System.setProperty(HardwareOptions.LOST_AFTER_PROPERTY, Long.toString(lostAfterMs));
        }
        try {
            return new RobotProgram(main, args.toArray(new String[0]), loader, name, quiet.quiet)
                    .run(spec.commandLine().getOut(), spec.commandLine().getErr());
        } finally {
            if (lostAfterMs != null) {
                if (before == null) {
                    System.clearProperty(HardwareOptions.LOST_AFTER_PROPERTY);
                } else {
                    System.setProperty(HardwareOptions.LOST_AFTER_PROPERTY, before);
                }
            }
        }
    }
}
