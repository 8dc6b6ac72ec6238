package robosim.cli;

import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
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
import robosim.hw.EnvironmentLinks;
import robosim.hw.HardwareOptions;
import robosim.hw.PioneerLink;
import robosim.hw.RuntimeChoices;

/**
 * {@code robosim robot}: runs a robot program in this JVM, as the original's
 * {@code java <robotApplication> robotName localhost portNumber}, and says in one line per robot how
 * its part in the run ended, with an exit code for it (see {@link RobotProgram}). With
 * {@code --pioneer HOST:PORT} the same program drives a Pioneer robot server instead of the
 * Environment (MobileSim, a real Pioneer behind a serial-to-TCP bridge, RoboSim's own Pioneer
 * port), through the system property {@value EnvironmentLinks#PIONEER_PROPERTY}.
 */
@Command(name = "robot", mixinStandardHelpOptions = true,
        customSynopsis = {"robosim robot [OPTIONS] CLASS NAME HOST PORT [ARGS...]",
                "       robosim robot [OPTIONS] --pioneer HOST:PORT CLASS NAME [ARGS...]"},
        description = {"Run a robot program: CLASS's main(NAME, HOST, PORT, ARGS...).",
                "HOST and PORT are the Environment's robot port; with --pioneer, the program drives the Pioneer robot"
                        + " server at HOST:PORT instead (MobileSim, a real Pioneer behind a serial-to-TCP bridge, or"
                        + " RoboSim's Pioneer port), in real time, and main gets that HOST and PORT.",
                "When the program and its robots are done, prints one line per robot: how its part in the run ended,"
                        + " the Environment's (or Pioneer server's) host:port, the last step and the reason."},
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

    @Parameters(index = "2..*", paramLabel = "ARGS",
            description = "without --pioneer: the Environment's HOST and robot PORT, then more arguments for the program;"
                    + " with --pioneer: more arguments for the program")
    List<String> rest = new ArrayList<>();

    @Option(names = "--pioneer", paramLabel = "HOST:PORT",
            description = "drive the Pioneer robot server at HOST:PORT (MobileSim, a real Pioneer through a serial-to-TCP"
                    + " bridge, RoboSim's Pioneer port) instead of an Environment; sets the system property "
                    + EnvironmentLinks.PIONEER_PROPERTY + ", which a program run with java alone can set too")
    String pioneer;

    @Option(names = "--lost-after", paramLabel = "MS",
            description = "declare the Environment lost after MS ms in which it sent nothing, neither a step nor a keep-alive"
                    + " (it sends one after each second without anything else); default: the system property "
                    + HardwareOptions.LOST_AFTER_PROPERTY + " if set, else " + HardwareOptions.DEFAULT_LOST_AFTER_MS
                    + " (a Pioneer server: MS ms without a status packet)")
    Long lostAfterMs;

    @Option(names = "--environment-timeout", paramLabel = "S",
            description = "seconds to wait for the Environment to listen and welcome the robots (it may be started"
                    + " after them); default: the system property " + HardwareOptions.CONNECT_TIMEOUT_PROPERTY
                    + " (ms) if set, else " + HardwareOptions.DEFAULT_CONNECT_TIMEOUT_MS / 1000)
    Long environmentTimeoutS;

    @Mixin
    SecretOption secret;

    @Option(names = {"--classpath", "--cp"}, paramLabel = "PATH",
            description = OptionTexts.CLASSPATH)
    String classpath;


    @Mixin
    QuietOption quiet;

    @Override
    public Integer call() throws Exception {
        List<String> args = new ArrayList<>(List.of(name));
        List<String> more;
        if (pioneer != null) {
            PioneerLink server;
            try {
                server = EnvironmentLinks.pioneer(pioneer, HardwareOptions.defaults());
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage().replace("the Pioneer robot server",
                        "--pioneer"));
            }
            args.add(server.host());
            args.add(Integer.toString(server.port()));
            more = rest;
        } else {
            if (rest.size() < 2) {
                throw new ParameterException(spec.commandLine(), "Missing required parameter"
                        + (rest.isEmpty() ? "s: 'HOST', 'PORT'" : ": 'PORT'") + " (the Environment's, after NAME;"
                        + " or give --pioneer HOST:PORT to drive a Pioneer robot server)");
            }
            args.add(rest.get(0));
            args.add(Integer.toString(port(rest.get(1))));
            more = rest.subList(2, rest.size());
        }
        args.addAll(more);
        String bad = secret.apply();
        if (bad != null) {
            throw new ParameterException(spec.commandLine(), bad);
        }
        if (lostAfterMs != null && (lostAfterMs < 1 || lostAfterMs > Integer.MAX_VALUE)) {
            throw new ParameterException(spec.commandLine(), lostAfterMs + " was supplied for --lost-after: it is 1 to "
                    + Integer.MAX_VALUE + " ms");
        }
        if (environmentTimeoutS != null && (environmentTimeoutS < 1 || environmentTimeoutS > Integer.MAX_VALUE / 1000)) {
            throw new ParameterException(spec.commandLine(), environmentTimeoutS + " was supplied for"
                    + " --environment-timeout: it is 1 to " + Integer.MAX_VALUE / 1000 + " s");
        }
        if (lostAfterMs == null || environmentTimeoutS == null) {
            try {
                HardwareOptions.defaults();
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage());
            }
        }
        try {
            RuntimeChoices.fromSystemProperties(); // the program's robots' runtime reads them as it is made
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        ClassLoader loader;
        try {
            loader = ProgramClasspath.loader(classpath);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
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
        // the program's robots read the lost time and the Pioneer server when they connect, without code of their own
        String lostBefore = set(HardwareOptions.LOST_AFTER_PROPERTY, lostAfterMs == null ? null : Long.toString(lostAfterMs));
        String pioneerBefore = set(EnvironmentLinks.PIONEER_PROPERTY, pioneer);
        String connectBefore = set(HardwareOptions.CONNECT_TIMEOUT_PROPERTY,
                environmentTimeoutS == null ? null : Long.toString(environmentTimeoutS * 1000));
        try {
            return new RobotProgram(main, args.toArray(new String[0]), loader, name, quiet.quiet)
                    .run(spec.commandLine().getOut(), spec.commandLine().getErr());
        } finally {
            restore(HardwareOptions.LOST_AFTER_PROPERTY, lostAfterMs, lostBefore);
            restore(EnvironmentLinks.PIONEER_PROPERTY, pioneer, pioneerBefore);
            restore(HardwareOptions.CONNECT_TIMEOUT_PROPERTY, environmentTimeoutS, connectBefore);
        }
    }

    private int port(String value) {
        try {
            int p = Integer.parseInt(value);
            if (p > 0 && p <= 65535) {
                return p;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new ParameterException(spec.commandLine(), value + " was supplied for PORT: a port is 1 to 65535");
    }

    /** Sets a system property if the value is given; @return its value before */
    private static String set(String property, String value) {
        String before = System.getProperty(property);
        if (value != null) {
            System.setProperty(property, value);
        }
        return before;
    }

    private static void restore(String property, Object given, String before) {
        if (given == null) {
            return;
        }
        if (before == null) {
            System.clearProperty(property);
        } else {
            System.setProperty(property, before);
        }
    }
}
