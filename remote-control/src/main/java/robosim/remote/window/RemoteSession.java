package robosim.remote.window;

import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.lang.reflect.InvocationTargetException;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Supplier;
import java.util.logging.Logger;
import javax.swing.SwingUtilities;
import robosim.remote.robot.RemoteRobot;
import robosim.viewer.net.ViewerClient;
import robosim.viewer.net.ViewerException;
import robosim.viewer.net.ViewerOptions;
import robosim.viewer.window.LiveFeed;
import robosim.viewer.window.ViewModel;

/**
 * A RemoteControl running: the robot on a thread of its own (the one that connected it, which is
 * then its program: it yields each step and takes the readings), a viewer connection feeding the
 * embedded view, and the window. {@link #close()} closes the window, leaves the run and detaches the
 * view, with every wait bounded.
 */
public final class RemoteSession implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(RemoteSession.class.getName());
    /** The longest {@link #close()} waits for the robot's and the viewer's threads, ms. */
    static final long CLOSE_WAIT_MS = 10_000;

    private final RemoteRobot robot;
    private final Thread robotThread;
    private final ViewerClient viewer;
    private final Thread viewerThread;
    private final RemoteWindow window;

    private RemoteSession(RemoteRobot robot, Thread robotThread, ViewerClient viewer, Thread viewerThread,
                          RemoteWindow window) {
        this.robot = robot;
        this.robotThread = robotThread;
        this.viewer = viewer;
        this.viewerThread = viewerThread;
        this.window = window;
    }

    /**
     * Connects the robot, attaches the view and shows the window.
     *
     * @param connect   connects the robot (on the robot's own thread); throws
     *                  {@link IllegalStateException} saying why it cannot
     * @param paramFile where the robot's parameters came from, for the parameters panel
     * @param view      the Environment's viewer port, or null for no embedded view
     * @param timeoutMs the longest wait for the robot to connect, ms
     * @return the running session
     * @throws IllegalStateException saying why the robot could not connect or no window could be opened
     * @throws InterruptedException  if interrupted
     */
    public static RemoteSession open(Supplier<RemoteRobot> connect, String paramFile, ViewerOptions view, long timeoutMs)
            throws InterruptedException {
        if (GraphicsEnvironment.isHeadless()) {
            throw new IllegalStateException("cannot open a window: Java runs headless (set DISPLAY)");
        }
        CompletableFuture<RemoteRobot> connected = new CompletableFuture<>();
        Thread robotThread = new Thread(() -> {
            RemoteRobot r;
            try {
                r = connect.get();
            } catch (RuntimeException e) {
                connected.completeExceptionally(e);
                return;
            }
            connected.complete(r);
            r.run();
        }, "remote-robot");
        robotThread.setDaemon(true);
        robotThread.start();
        RemoteRobot robot = awaitRobot(connected, timeoutMs, robotThread);
        ViewModel model = view == null ? null : new ViewModel();
        RemoteWindow[] window = new RemoteWindow[1];
        try {
            SwingUtilities.invokeAndWait(() -> {
                window[0] = new RemoteWindow(robot, paramFile, model);
                window[0].show();
            });
        } catch (InvocationTargetException | HeadlessException | AWTError e) {
            robot.disconnect();
            Throwable cause = e instanceof InvocationTargetException i ? i.getCause() : e;
            throw new IllegalStateException("cannot open the window: " + cause, cause);
        }
        ViewerClient client = null;
        Thread viewerThread = null;
        if (view != null) {
            model.source("live from " + view.peer());
            client = new ViewerClient(view.withName("remote:" + robot.name()), List.of(new LiveFeed(model)));
            ViewerClient c = client;
            viewerThread = new Thread(() -> {
                try {
                    c.run();
                } catch (ViewerException | RuntimeException e) {
                    LOG.warning(() -> "remote " + robot.name() + ": the view ended: " + e.getMessage());
                    SwingUtilities.invokeLater(() -> model.ended(e.getMessage()));
                }
            }, "remote-view");
            viewerThread.setDaemon(true);
            viewerThread.start();
        }
        return new RemoteSession(robot, robotThread, client, viewerThread, window[0]);
    }

    private static RemoteRobot awaitRobot(CompletableFuture<RemoteRobot> connected, long timeoutMs, Thread thread)
            throws InterruptedException {
        try {
            return connected.get(timeoutMs, TimeUnit.MILLISECONDS);
        } catch (ExecutionException e) {
            throw e.getCause() instanceof IllegalStateException s ? s
                    : new IllegalStateException("the robot could not connect: " + e.getCause(), e.getCause());
        } catch (TimeoutException e) {
            thread.interrupt();
            throw new IllegalStateException("the robot did not connect within " + timeoutMs + " ms");
        }
    }

    /** @return the robot */
    public RemoteRobot robot() {
        return robot;
    }

    /** @return the window */
    public RemoteWindow window() {
        return window;
    }

    /**
     * Waits until the user closes the window or the robot's part in the run ends.
     *
     * @throws InterruptedException if interrupted
     */
    public void awaitEnd() throws InterruptedException {
        while (!window.awaitClosed(200) && robot.runEnd() == null) {
            // polled: either may end first, and each has its own way of saying so
        }
    }

    @Override
    public void close() throws InterruptedException {
        SwingUtilities.invokeLater(window::close);
        robot.disconnect();
        if (viewer != null) {
            viewer.stop();
            viewerThread.join(CLOSE_WAIT_MS);
        }
        robotThread.join(CLOSE_WAIT_MS);
        window.awaitClosed(CLOSE_WAIT_MS);
    }
}
