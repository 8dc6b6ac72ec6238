package robosim.it;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;

/**
 * Network namespaces standing in for machines of their own, joined by veth links through a router
 * namespace, as a small routed network:
 *
 * <pre>
 *   env  10.77.0.1/30 ── 10.77.0.2  router  10.77.1.1 ── 10.77.1.2/30  robots 1
 *                                           10.77.2.1 ── 10.77.2.2/30  robots 2 ...
 * </pre>
 *
 * The router forwards between the links, so a robot reaches the Environment at
 * {@link #ENV_ADDRESS}; latency can be added on the router's interfaces ({@link #addNetem}) or by a
 * relay running in the router ({@link DelayRelay}). Namespace names are
 * {@code robosim-it-PID-RANDOM-ROLE}; {@link #close()} ends whatever still runs in them and deletes
 * them, and {@link #create} first deletes those a test JVM that is gone left behind. Needs Linux,
 * iproute2's {@code ip} (and {@code tc} for netem) and root.
 */
final class NetworkNamespaces implements AutoCloseable {
    /** How every namespace these tests make is named first. */
    static final String PREFIX = "robosim-it-";
    /** The Environment's address, on its link to the router. */
    static final String ENV_ADDRESS = "10.77.0.1";
    private static final int COMMAND_SECONDS = 20;

    /** Namespaces cannot be made here; the message says why. */
    static final class Unavailable extends Exception {
        Unavailable(String message) {
            super(message);
        }
    }

    private final String ip;
    private final String name;
    private final List<String> made = new ArrayList<>();
    private final int robotNamespaces;

    private NetworkNamespaces(String ip, int robotNamespaces) {
        this.ip = ip;
        this.robotNamespaces = robotNamespaces;
        String random = String.format("%06x", ThreadLocalRandom.current().nextInt(1 << 24));
        this.name = PREFIX + ProcessHandle.current().pid() + "-" + random;
    }

    /**
     * Makes the Environment's, the router's and the robots' namespaces and links them.
     *
     * @param robotNamespaces how many namespaces for robots, 1 to 200
     * @return the namespaces, to be closed
     * @throws Unavailable if this machine cannot make network namespaces (not Linux, no {@code ip},
     *                     not root): the test is to be skipped
     */
    static NetworkNamespaces create(int robotNamespaces) throws Unavailable, IOException, InterruptedException {
        if (robotNamespaces < 1 || robotNamespaces > 200) {
            throw new IllegalArgumentException(robotNamespaces + " was supplied for robotNamespaces: it must be 1 to 200");
        }
        if (!System.getProperty("os.name").startsWith("Linux")) {
            throw new Unavailable("network namespaces are Linux's; this is " + System.getProperty("os.name"));
        }
        String ip = tool("ip").orElseThrow(
                () -> new Unavailable("no ip command (iproute2) in /usr/sbin, /sbin, /usr/bin or /bin"));
        NetworkNamespaces net = new NetworkNamespaces(ip, robotNamespaces);
        deleteStale(ip);
        String env = net.env();
        Result add = run(ip, "netns", "add", env);
        if (add.exit() != 0) {
            throw new Unavailable("ip netns add failed (it needs root, with CAP_SYS_ADMIN): " + add.output());
        }
        net.made.add(env);
        Result exec = run(ip, "netns", "exec", env, "true");
        if (exec.exit() != 0) {
            net.close();
            throw new Unavailable("ip netns exec failed (it needs root and mount rights): " + exec.output());
        }
        try {
            net.link();
        } catch (IOException | RuntimeException e) {
            net.close();
            throw e;
        }
        return net;
    }

    private void link() throws IOException, InterruptedException {
        for (String ns : namespacesAfterEnv()) {
            must(ip, "netns", "add", ns);
            made.add(ns);
        }
        for (String ns : made) {
            must(ip, "-n", ns, "link", "set", "lo", "up");
        }
        must(ip, "-n", env(), "link", "add", "to-router", "type", "veth", "peer", "name", "to-env", "netns", router());
        must(ip, "-n", env(), "addr", "add", ENV_ADDRESS + "/30", "dev", "to-router");
        must(ip, "-n", env(), "link", "set", "to-router", "up");
        must(ip, "-n", router(), "addr", "add", "10.77.0.2/30", "dev", "to-env");
        must(ip, "-n", router(), "link", "set", "to-env", "up");
        must(ip, "-n", env(), "route", "add", "default", "via", "10.77.0.2");
        for (int i = 1; i <= robotNamespaces; i++) {
            String ns = robots(i);
            must(ip, "-n", router(), "link", "add", "to-robots" + i, "type", "veth",
                    "peer", "name", "to-router", "netns", ns);
            must(ip, "-n", router(), "addr", "add", gateway(i) + "/30", "dev", "to-robots" + i);
            must(ip, "-n", router(), "link", "set", "to-robots" + i, "up");
            must(ip, "-n", ns, "addr", "add", "10.77." + i + ".2/30", "dev", "to-router");
            must(ip, "-n", ns, "link", "set", "to-router", "up");
            must(ip, "-n", ns, "route", "add", "default", "via", gateway(i));
        }
        // /proc/sys/net is the namespace of the process that opens it
        must(ip, "netns", "exec", router(), "sh", "-c", "echo 1 > /proc/sys/net/ipv4/ip_forward");
    }

    private List<String> namespacesAfterEnv() {
        List<String> names = new ArrayList<>(List.of(router()));
        for (int i = 1; i <= robotNamespaces; i++) {
            names.add(robots(i));
        }
        return names;
    }

    /** @return the Environment's namespace */
    String env() {
        return name + "-env";
    }

    /** @return the router's namespace, between the others */
    String router() {
        return name + "-router";
    }

    /**
     * @param i 1 to the number of robot namespaces
     * @return robot namespace i
     */
    String robots(int i) {
        return name + "-robots" + i;
    }

    /**
     * @param i 1 to the number of robot namespaces
     * @return the router's address on robot namespace i's link, where a relay in the router is reached
     */
    String gateway(int i) {
        return "10.77." + i + ".1";
    }

    /**
     * @param ns a namespace made here
     * @return the command prefix that runs a program in it
     */
    List<String> exec(String ns) {
        return List.of(ip, "netns", "exec", ns);
    }

    /**
     * Adds {@code tc netem} latency on every interface of the router, so every packet between the
     * Environment and a robot is delayed once on its way, in either direction.
     *
     * @param delayMs  the mean delay
     * @param jitterMs how far a delay may be from the mean
     * @return empty if netem was added; otherwise why not (no {@code tc}, or a kernel without netem)
     */
    Optional<String> addNetem(int delayMs, int jitterMs) throws IOException, InterruptedException {
        Optional<String> tc = tool("tc");
        if (tc.isEmpty()) {
            return Optional.of("no tc command");
        }
        List<String> interfaces = new ArrayList<>(List.of("to-env"));
        for (int i = 1; i <= robotNamespaces; i++) {
            interfaces.add("to-robots" + i);
        }
        for (String dev : interfaces) {
            Result r = run(tc.get(), "-n", router(), "qdisc", "add", "dev", dev, "root", "netem",
                    "delay", delayMs + "ms", jitterMs + "ms");
            if (r.exit() != 0) {
                return Optional.of("tc qdisc add ... netem: " + r.output());
            }
        }
        return Optional.empty();
    }

    /** Ends every process still in the namespaces made here and deletes them. */
    @Override
    public void close() throws IOException, InterruptedException {
        List<String> failures = new ArrayList<>();
        for (String ns : made) {
            delete(ip, ns, failures);
        }
        made.clear();
        if (!failures.isEmpty()) {
            throw new IllegalStateException("network namespaces left behind: " + failures);
        }
    }

    /** Deletes the namespaces of this prefix whose test JVM has ended. */
    private static void deleteStale(String ip) throws IOException, InterruptedException {
        for (String line : must(ip, "netns", "list").split("\n")) {
            String ns = line.split(" ")[0];
            if (!ns.startsWith(PREFIX)) {
                continue;
            }
            String pid = ns.substring(PREFIX.length()).split("-")[0];
            boolean ownerGone = !pid.matches("[0-9]{1,18}")
                    || ProcessHandle.of(Long.parseLong(pid)).map(p -> !p.isAlive()).orElse(true);
            if (ownerGone) {
                List<String> failures = new ArrayList<>();
                delete(ip, ns, failures);
                System.err.println("NetworkNamespaces: " + ns + " was left behind by a test JVM that has ended: "
                        + (failures.isEmpty() ? "deleted" : "cannot delete it: " + failures));
            }
        }
    }

    private static void delete(String ip, String ns, List<String> failures) throws IOException, InterruptedException {
        Result pids = run(ip, "netns", "pids", ns);
        for (String pid : pids.output().split("\\s+")) {
            if (pid.matches("[0-9]{1,18}")) {
                ProcessHandle.of(Long.parseLong(pid)).ifPresent(p -> {
                    p.destroyForcibly();
                    p.onExit().orTimeout(10, TimeUnit.SECONDS).exceptionally(t -> null).join();
                });
            }
        }
        Result del = run(ip, "netns", "delete", ns);
        if (del.exit() != 0) {
            failures.add(ns + ": " + del.output());
        }
    }

    private static Optional<String> tool(String name) {
        for (String dir : List.of("/usr/sbin", "/sbin", "/usr/bin", "/bin")) {
            Path p = Path.of(dir, name);
            if (Files.isExecutable(p)) {
                return Optional.of(p.toString());
            }
        }
        return Optional.empty();
    }

    /** A command's exit code and output (standard output and error together, trimmed). */
    private record Result(int exit, String output) { }

    private static Result run(String... cmd) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        try {
            if (!p.waitFor(COMMAND_SECONDS, TimeUnit.SECONDS)) {
                return new Result(-1, String.join(" ", cmd) + " did not end within " + COMMAND_SECONDS + " s");
            }
            String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            return new Result(p.exitValue(), output.trim());
        } finally {
            p.destroyForcibly();
        }
    }

    private static String must(String... cmd) throws IOException, InterruptedException {
        Result r = run(cmd);
        if (r.exit() != 0) {
            throw new IllegalStateException(String.join(" ", cmd) + " failed with exit code " + r.exit() + ": "
                    + r.output());
        }
        return r.output();
    }
}
