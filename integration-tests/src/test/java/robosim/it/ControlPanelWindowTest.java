package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.Component;
import java.awt.Container;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import javax.imageio.ImageIO;
import javax.swing.AbstractButton;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.panel.window.ControlPanelWindow;
import robosim.panel.window.RunForm;
import robosim.protocol.Await;
import robosim.viewer.window.Displays;

/**
 * The ControlPanel as a user works it, in a real window (under Xvfb in CI), against a live
 * Environment in world {@code empty-room.xml}: its buttons clicked (some with the mouse through
 * {@link Robot}, the rest with {@code doClick}), and the Environment's state checked after each.
 * The robots are Wander programs the panel starts in JVMs of their own. With
 * {@code -Drobosim.screenshots=DIR} it saves a screenshot of the window as {@code control-panel.png}.
 */
@Timeout(value = 4, unit = TimeUnit.MINUTES)
class ControlPanelWindowTest {
    private ControlPanelWindow window;

    @AfterEach
    void close() throws Exception {
        if (window != null) {
            SwingUtilities.invokeAndWait(window::dispose);
            window.awaitClosed();
        }
    }

    private static void await(String what, BooleanSupplier condition) {
        Await.until(Duration.ofSeconds(60), what, condition);
    }

    private <T> T onEdt(java.util.function.Supplier<T> read) throws Exception {
        AtomicReference<T> v = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> v.set(read.get()));
        return v.get();
    }

    private Component named(String name) throws Exception {
        return onEdt(() -> find(window, name));
    }

    private static Component find(Container c, String name) {
        for (Component child : c.getComponents()) {
            if (name.equals(child.getName())) {
                return child;
            }
            if (child instanceof Container inner) {
                Component found = find(inner, name);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }

    private void click(String button) throws Exception {
        AbstractButton b = (AbstractButton) named(button);
        SwingUtilities.invokeAndWait(b::doClick);
    }

    /** Clicks a button with the mouse, as a user does. */
    private void mouseClick(String button) throws Exception {
        Component b = named(button);
        Rectangle r = onEdt(() -> {
            Point p = b.getLocationOnScreen();
            return new Rectangle(p.x, p.y, b.getWidth(), b.getHeight());
        });
        Robot robot = new Robot();
        robot.setAutoWaitForIdle(true);
        robot.mouseMove(r.x + r.width / 2, r.y + r.height / 2);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.waitForIdle();
    }

    private void type(String field, String text) throws Exception {
        JTextField f = (JTextField) named(field);
        SwingUtilities.invokeAndWait(() -> f.setText(text));
    }

    private String log() throws Exception {
        return onEdt(() -> window.log().text());
    }

    private boolean connected(LocalEnvironment h, String robot) {
        return h.sim.snapshot().robots().stream().anyMatch(r -> r.name().equals(robot) && r.connected());
    }

    private void addWanderer(String name) throws Exception {
        type("program", "robosim.examples.wander.Wander");
        type("robotName", name);
        click("addRobot");
    }

    @Test
    void startPauseStepAddMoveRemoveAndStopThroughTheWindow() throws Exception {
        String why = Displays.unavailable();
        if (why != null) {
            System.err.println("ControlPanelWindowTest skipped: " + why);
        }
        assumeTrue(why == null, why);
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback())) {
            SwingUtilities.invokeAndWait(() -> {
                window = new ControlPanelWindow(RunForm.worldsIn(LocalEnvironment.root()
                        .resolve("testLoadFiles/environment")), null);
                window.setVisible(true);
                window.attach("127.0.0.1", h.viewerPort(), h.robotPort(), null);
            });
            await("attached", () -> uncheck(() -> log().contains("attached to the Environment")));

            mouseClick("pause");
            addWanderer("r1");
            addWanderer("r2");
            await("both robots connected", () -> connected(h, "r1") && connected(h, "r2"));
            await("the pause answered", () -> uncheck(() -> log().contains("pause: paused after step 0")));
            assertEquals(0, h.sim.stepCount(), "paused before the first step");

            type("steps", "3");
            mouseClick("step");
            await("3 steps run", () -> uncheck(() -> log().contains("ran 3 steps; paused after step 3")));
            assertEquals(3, h.sim.stepCount());
            await("the table shows both robots", () -> uncheck(() -> onEdt(() -> window.robots().table()
                    .getRowCount()) == 2 && window.controls().line().contains("step 3")));

            click("resume");
            await("steps run after resume", () -> h.sim.stepCount() > 10);
            click("pause");
            // the first pause's line ("paused after step 0") is in the log already: wait for the second's
            await("paused again", () -> uncheck(() -> log().split("pause: paused after step ", -1).length > 2));
            long paused = h.sim.stepCount();
            Thread.sleep(300); // a wait for something NOT to happen: no condition marks it
            assertEquals(paused, h.sim.stepCount(), "no step runs while paused");

            SwingUtilities.invokeAndWait(() -> assertTrue(window.robots().select("r1")));
            type("x", "3000");
            type("y", "1500");
            type("th", "90");
            click("move");
            await("r1 moved", () -> h.sim.summary("r1").x() == 3000.0);
            assertEquals(1500.0, h.sim.summary("r1").y());

            screenshotIfAsked();

            SwingUtilities.invokeAndWait(() -> assertTrue(window.robots().select("r2")));
            mouseClick("remove");
            await("r2 removed", () -> !connected(h, "r2"));
            assertTrue(connected(h, "r1"), "r1 stays");

            type("commsLatency", "2");
            click("applyComms");
            await("the latency changed", () -> h.sim.commsSettings().latencySteps() == 2);

            click("stop");
            RunReport report = h.await(60);
            assertEquals("stopped by control client control-panel", report.endReason());
            assertFalse(log().contains("refused"), log());
            // the run's line says the run stopped, and the panel stops asking for statuses aloud
            await("the line says stopped", () -> uncheck(() -> onEdt(() -> window.controls().line())
                    .startsWith("stopped: ")));
            assertFalse(log().contains("no status from"), log());
        }
    }

    @Test
    void attachedItShowsTheEnvironmentsLogLoadsAnotherWorldAndRestartsIt() throws Exception {
        String why = Displays.unavailable();
        if (why != null) {
            System.err.println("ControlPanelWindowTest skipped: " + why);
        }
        assumeTrue(why == null, why);
        Path worlds = LocalEnvironment.root().resolve("testLoadFiles/environment");
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback())) {
            SwingUtilities.invokeAndWait(() -> {
                window = new ControlPanelWindow(RunForm.worldsIn(worlds), null);
                window.setVisible(true);
                window.attach("127.0.0.1", h.viewerPort(), h.robotPort(), null);
            });
            await("attached", () -> uncheck(() -> log().contains("attached to the Environment")));
            click("pause");
            addWanderer("r1");
            addWanderer("r2");
            await("both robots connected", () -> connected(h, "r1") && connected(h, "r2"));
            // the Environment's own lines, forwarded to a panel that did not start it
            await("the Environment's log in the pane", () -> uncheck(() -> log().contains("] SessionRules: robot r1 connected")
                    || log().contains("] RobotJoins: robot r1 connected")));

            javax.swing.JComboBox<?> world = (javax.swing.JComboBox<?>) named("world");
            SwingUtilities.invokeAndWait(() -> world.setSelectedItem(worlds.resolve("small-maze.xml").toString()));
            mouseClick("load");
            await("the new world waits for its robots", () -> uncheck(() -> log().contains(
                    "load of world small-maze by control client control-panel after step 0: world small-maze (seed 1)"
                            + " waits for its robots")));
            await("the table shows the new world", () -> uncheck(() -> onEdt(() -> window.controls().line())
                    .startsWith("world small-maze - step 0")));
            assertTrue(log().contains("the robots started for the old world were disconnected"), log());

            click("restart");
            await("the Environment restarted its run", () -> uncheck(() -> log().contains(
                    "restart: restart by control client control-panel after step 0: world small-maze")));

            click("stop");
            RunReport report = h.await(60);
            assertEquals("stopped by control client control-panel", report.endReason());
        }
    }

    /** @return the pids the log gives for what it says was started ("started an Environment", "started robot r1") */
    private List<Long> pids(String started) throws Exception {
        List<Long> pids = new ArrayList<>();
        Matcher m = Pattern.compile(Pattern.quote(started) + "[^\\n]*pid (\\d+)\\)").matcher(log());
        while (m.find()) {
            pids.add(Long.parseLong(m.group(1)));
        }
        return pids;
    }

    private static boolean alive(long pid) {
        return ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false);
    }

    @Test
    void startsAnEnvironmentInAJvmOfItsOwnRestartsItWithItsRobotsAndStopsThemWhenClosed() throws Exception {
        String why = Displays.unavailable();
        if (why != null) {
            System.err.println("ControlPanelWindowTest skipped: " + why);
        }
        assumeTrue(why == null, why);
        Path room = LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml");
        SwingUtilities.invokeAndWait(() -> {
            window = new ControlPanelWindow(RunForm.worldsIn(room.getParent()), room);
            window.setVisible(true);
        });
        mouseClick("start");
        await("attached to the Environment started", () -> uncheck(() -> log().contains("attached to the Environment")));
        addWanderer("r1");
        addWanderer("r2");
        await("the run under way with both robots", () -> uncheck(() -> onEdt(() -> window.controls().line())
                .matches("world empty-room - step [1-9]\\d* .* 2 of 2 robots connected")));
        long first = pids("started an Environment").get(0);

        click("restart");
        await("a second Environment", () -> uncheck(() -> pids("started an Environment").size() == 2));
        long second = pids("started an Environment").get(1);
        await("the first Environment ended", () -> !alive(first));
        await("the robots started again", () -> uncheck(() -> pids("started robot").size() == 4));
        await("the new run under way with both robots", () -> uncheck(() -> log().split("attached to the Environment",
                -1).length == 3 && onEdt(() -> window.controls().line()).matches(".* 2 of 2 robots connected")));
        List<Long> robots = pids("started robot");

        SwingUtilities.invokeAndWait(window::dispose);
        window.awaitClosed();
        window = null;

        assertFalse(alive(second), "the Environment the panel started ends with the panel");
        for (long r : robots) {
            assertFalse(alive(r), "robot JVM " + r + " ends with the panel");
        }
    }

    private void screenshotIfAsked() throws Exception {
        String dir = System.getProperty("robosim.screenshots");
        if (dir == null || dir.isBlank()) {
            return;
        }
        await("the table shows r1 moved", () -> uncheck(() -> onEdt(() -> {
            javax.swing.JTable table = window.robots().table();
            for (int row = 0; row < table.getRowCount(); row++) {
                if (table.getValueAt(row, 0).equals("r1") && table.getValueAt(row, 3).toString().startsWith("3000, 1500")) {
                    return true;
                }
            }
            return false;
        })));
        new Robot().waitForIdle();
        Rectangle bounds = onEdt(() -> {
            Point p = window.getLocationOnScreen();
            return new Rectangle(p.x, p.y, window.getWidth(), window.getHeight());
        });
        BufferedImage image = new Robot().createScreenCapture(bounds);
        Path out = Path.of(dir).resolve("control-panel.png");
        Files.createDirectories(out.getParent());
        ImageIO.write(image, "png", out.toFile());
    }

    private interface Check {
        boolean get() throws Exception;
    }

    private static boolean uncheck(Check c) {
        try {
            return c.get();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }
}
