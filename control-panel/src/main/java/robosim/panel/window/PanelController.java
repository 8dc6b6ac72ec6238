package robosim.panel.window;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.logging.Level;
import java.util.logging.Logger;
import javax.swing.SwingUtilities;
import robosim.panel.model.CommsChange;
import robosim.panel.model.EnvironmentLine;
import robosim.panel.model.Request;
import robosim.panel.model.RobotLaunch;
import robosim.panel.model.RunSettings;
import robosim.panel.net.PanelSession;
import robosim.panel.net.PanelView;
import robosim.panel.process.ChildJvm;
import robosim.panel.process.RunProcesses;
import robosim.protocol.CommsUpdate;
import robosim.protocol.RunSecret;
import robosim.protocol.RunStatus;
import robosim.viewer.net.ViewerOptions;
import robosim.viewer.window.LiveFeed;
import robosim.viewer.window.ViewModel;

/**
 * What the panel's buttons do, off the event thread: starting an Environment and robots in JVMs of
 * their own, attaching (two control connections and a viewer), sending requests. Every result comes
 * back to the window on the event thread. Called on the event thread; never blocks it.
 */
final class PanelController implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(PanelController.class.getName());
    /** How often the table is refreshed, ms. */
    static final long STATUS_PERIOD_MS = 500;
    /** How long a robot added with a pose has to join before it is placed, ms. */
    static final long JOIN_WAIT_MS = 60_000;

    private final ViewModel model;
    private final RunProcesses processes;
    private final Consumer<String> log;
    private final Consumer<RunStatus> statuses;
    private final Consumer<String> lines;
    private final ExecutorService work = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "panel-work");
        t.setDaemon(true);
        return t;
    });
    private volatile PanelSession session;
    private volatile PanelView view;
    private volatile RunStatus last;
    private volatile String robotHost;
    private volatile int robotPort;
    private volatile int viewerPort;
    private volatile RunSettings lastRun;
    private final List<RobotLaunch> launched = new CopyOnWriteArrayList<>();

    /**
     * @param model    the live view's model, fed by the viewer
     * @param log      the log (any thread)
     * @param statuses gets each status, on the event thread
     * @param lines    gets the run's line while no status comes (waiting, gone, stopped), on the event thread
     */
    PanelController(ViewModel model, Consumer<String> log, Consumer<RunStatus> statuses, Consumer<String> lines) {
        this.model = model;
        this.log = log;
        this.statuses = statuses;
        this.lines = lines;
        this.processes = new RunProcesses(null, log);
    }

    /** Starts a new Environment with these settings and attaches once it listens. */
    void start(RunSettings settings) {
        lastRun = settings;
        work.execute(() -> {
            try {
                detach();
                ChildJvm env = processes.startEnvironment(settings, where -> work.execute(() -> attachStarted(where)));
                log.accept("panel: started an Environment (pid " + env.pid() + ") on " + settings.world());
            } catch (IOException | IllegalStateException e) {
                log.accept("panel: cannot start the Environment: " + e.getMessage());
            }
        });
    }

    private void attachStarted(EnvironmentLine where) {
        try {
            String token = processes.secret();
            if (token != null) {
                // the viewer finds the secret where every client does: this JVM's property
                System.setProperty(RunSecret.PROPERTY, token);
            }
            attach(where.clientHost(), where.viewerPort(), where.robotPort(), token);
        } catch (IOException | IllegalArgumentException e) {
            log.accept("panel: cannot read the run secret: " + e.getMessage());
        }
    }

    /**
     * Attaches to a running Environment, or one about to start: control connections and a viewer,
     * each looking the run secret up again whenever it connects, and trying again until it answers.
     */
    void attach(String host, int viewerPort, int robots, String token) {
        work.execute(() -> {
            detach();
            robotHost = host;
            robotPort = robots;
            this.viewerPort = viewerPort;
            PanelSession s = new PanelSession(host, viewerPort, token);
            session = s;
            log.accept("panel: attached to the Environment at " + s.peer());
            SwingUtilities.invokeLater(() -> lines.accept("attaching to the Environment at " + s.peer() + "..."));
            if (!processes.environmentRuns()) {
                // an Environment this panel started writes its log to the pane already, through its output
                s.followLog(line -> log.accept("env: " + line));
            }
            s.poll(STATUS_PERIOD_MS, st -> {
                last = st;
                SwingUtilities.invokeLater(() -> statuses.accept(st));
            }, line -> SwingUtilities.invokeLater(() -> lines.accept(line)), why -> log.accept("panel: " + why));
            PanelView v = new PanelView(ViewerOptions.of(host, viewerPort).withName("control-panel"),
                    new LiveFeed(model), why -> log.accept("panel: view: " + why));
            view = v;
            work.execute(v::run);
        });
    }

    /** Sends a request; its answer goes to the log. */
    CompletableFuture<Void> send(Request r) {
        PanelSession s = session;
        if (s == null) {
            log.accept("panel: " + r + ": not attached to an Environment (Start one, or Attach)");
            return CompletableFuture.completedFuture(null);
        }
        return s.send(r).handle((reply, failure) -> {
            if (failure != null) {
                log.accept("panel: " + (failure.getCause() != null ? failure.getCause() : failure).getMessage());
            } else {
                log.accept("panel: " + r + ": " + (reply.ok() ? "" : "refused: ") + reply.text());
                if (reply.ok() && r.op().equals("load")) {
                    loaded();
                }
            }
            return null;
        });
    }

    /**
     * Another world runs now: the robots this panel started belonged to the old one and have been
     * disconnected, and Restart from now on restarts the loaded world in the Environment.
     */
    private void loaded() {
        if (!launched.isEmpty()) {
            log.accept("panel: the robots started for the old world were disconnected; add the new world's robots");
        }
        launched.clear();
        lastRun = null;
    }

    /** Changes the comms settings; the settings now in force go to the log. */
    void comms(CommsUpdate change) {
        PanelSession s = session;
        if (s == null) {
            log.accept("panel: comms: not attached to an Environment (Start one, or Attach)");
            return;
        }
        s.comms(change).whenComplete((now, failure) -> log.accept("panel: " + (failure != null
                ? (failure.getCause() != null ? failure.getCause() : failure).getMessage()
                : "comms settings now: " + CommsChange.describe(now))));
    }

    /** Starts a robot program in a JVM of its own, and places it once it has joined if a pose was given. */
    void addRobot(RobotLaunch launch) {
        if (session == null || robotPort == 0) {
            log.accept("panel: add robot " + launch.name() + ": " + (session == null ? "not attached to an Environment"
                    : "the robot port is not known: give it when attaching"));
            return;
        }
        launched.add(launch);
        work.execute(() -> {
            try {
                ChildJvm jvm = processes.startRobot(launch, robotHost, robotPort);
                log.accept("panel: started robot " + launch.name() + " (" + launch.program() + ", pid " + jvm.pid() + ")");
                if (launch.placementRequest().isPresent()) {
                    placeOnceJoined(launch, jvm);
                }
            } catch (IOException e) {
                log.accept("panel: cannot start robot " + launch.name() + ": " + e.getMessage());
            }
        });
    }

    private void placeOnceJoined(RobotLaunch launch, ChildJvm jvm) {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(JOIN_WAIT_MS);
        try {
            while (System.nanoTime() < end && jvm.isAlive()) {
                RunStatus s = last;
                if (s != null && s.robots().stream().anyMatch(r -> r.name().equals(launch.name()) && r.connected())) {
                    send(launch.placementRequest().get());
                    return;
                }
                Thread.sleep(STATUS_PERIOD_MS);
            }
            log.accept("panel: robot " + launch.name() + " did not join within " + JOIN_WAIT_MS / 1000
                    + " s; it was not placed");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Opens a RemoteControl window on a robot, in a JVM of its own. */
    void openRemote(String robot) {
        if (session == null || robotPort == 0) {
            log.accept("panel: RemoteControl for " + robot + ": not attached, or the robot port is not known");
            return;
        }
        work.execute(() -> {
            try {
                ChildJvm jvm = processes.startTool("remote " + robot, List.of("remote", robot, robotHost,
                        Integer.toString(robotPort), "--viewer-port", Integer.toString(viewerPort)));
                Integer code = jvm.waitFor(5000);
                if (code != null && code != 0) {
                    log.accept("panel: RemoteControl for " + robot + " ended at once (exit " + code + "); the log"
                            + " above says why");
                }
            } catch (IOException e) {
                log.accept("panel: cannot start RemoteControl for " + robot + ": " + e.getMessage());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
    }

    /**
     * Restarts a run this panel started: stops its Environment and robots, starts them again with
     * the same settings and programs. An Environment the panel attached to, or one that has loaded
     * another world, is asked to {@code restart} (its robots are disconnected and must connect again).
     */
    void restart() {
        if (lastRun == null) {
            // an Environment the panel attached to (or one that loaded another world) restarts itself
            send(Request.restart());
            return;
        }
        List<RobotLaunch> robots = List.copyOf(launched);
        launched.clear();
        work.execute(() -> {
            detach();
            processes.stopAll();
            log.accept("panel: restarting: " + lastRun.world() + " with " + robots.size() + " robot(s)");
            start(lastRun);
            for (RobotLaunch r : robots) {
                awaitAttached();
                addRobot(r);
            }
        });
    }

    private void awaitAttached() {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (robotPort == 0 && System.nanoTime() < end) {
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    private void detach() {
        PanelSession s = session;
        session = null;
        robotPort = 0;
        last = null;
        if (s != null) {
            s.close();
        }
        PanelView v = view;
        view = null;
        if (v != null) {
            v.stop();
        }
    }

    /** Detaches, and stops every JVM the panel started. Bounded. */
    @Override
    public void close() {
        detach();
        try {
            processes.close();
        } catch (IOException e) {
            LOG.log(Level.WARNING, "cannot remove the panel's secret file", e);
        }
        work.shutdownNow();
    }
}
