package robosim.remote.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.Component;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.params.RobotParameterFiles;
import robosim.protocol.Snapshot;
import robosim.remote.LiveEnvironment;
import robosim.remote.robot.PioneerRemote;
import robosim.viewer.net.ViewerOptions;
import robosim.viewer.window.Displays;

/**
 * The RemoteControl's window on a real display (Xvfb in CI), driving a robot in a live Environment
 * as a user does: a mouse click on Forward, then Stop; the up arrow held, then released. After each,
 * the Environment's true state says what the robot did. With {@code -Drobosim.screenshots=DIR} it
 * also saves the window as {@code DIR/remote-control.png}, the README's picture.
 */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class RemoteWindowTest {
    private static final String ROOM = """
            <?xml version="1.0" encoding="UTF-8"?>
            <world name="room" width="8000" height="6000" stepMs="100" boundary="true">
              <polygon points="5000,2200 5600,2200 5600,3800 5000,3800" height="500"/>
              <polygon points="2500,4400 3100,4400 3100,5000 2500,5000" height="500"/>
              <robot name="r1" type="pioneer" x="1500" y="3000" th="0" params="%ROBOTS%/p3dx.p"/>
            </world>
            """;

    @TempDir
    Path dir;
    private LiveEnvironment env;
    private RemoteSession session;
    private Robot mouse;

    @BeforeEach
    void open() throws Exception {
        String why = Displays.unavailable();
        if (why != null) {
            System.err.println("RemoteWindowTest skipped: " + why);
        }
        assumeTrue(why == null, why);
        env = new LiveEnvironment(dir, ROOM);
        session = RemoteSession.open(() -> PioneerRemote.connect("r1", "127.0.0.1", env.robotPort(),
                RobotParameterFiles.load("p3dx")), "p3dx", ViewerOptions.of("127.0.0.1", env.viewerPort()), 20_000);
        mouse = new Robot();
        mouse.setAutoDelay(20);
        assertTrue(LiveEnvironment.await(() -> env.robot("r1") != null && onEdt(() -> session.window().frame().isShowing()),
                20_000), "the run started and the window shows");
    }

    @AfterEach
    void close() throws Exception {
        if (session != null) {
            session.close();
        }
        if (env != null) {
            env.close();
        }
    }

    private static <T> T onEdt(Callable<T> task) {
        AtomicReference<T> result = new AtomicReference<>();
        try {
            SwingUtilities.invokeAndWait(() -> {
                try {
                    result.set(task.call());
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
        return result.get();
    }

    /** Clicks a component's centre with the real mouse. */
    private void click(String name) {
        Point at = onEdt(() -> {
            Component c = session.window().find(name);
            Point p = c.getLocationOnScreen();
            return new Point(p.x + c.getWidth() / 2, p.y + c.getHeight() / 2);
        });
        mouse.mouseMove(at.x, at.y);
        mouse.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        mouse.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
    }

    private Snapshot.RobotView r1() {
        return env.robot("r1");
    }

    /** Waits for the robot to stand still, then checks it stays where it is. */
    private void assertStops() throws Exception {
        assertTrue(LiveEnvironment.await(() -> r1().vel() == 0 && r1().rotVel() == 0, 5_000), "stops: " + r1());
        double x = r1().x();
        assertTrue(env.awaitSteps(5), "the run goes on");
        assertEquals(x, r1().x(), 1e-6, "stays stopped");
    }

    @Test
    void clickingForwardDrivesTheRobotAndClickingStopStopsIt() throws Exception {
        double x0 = r1().x();
        click("forward");
        assertTrue(LiveEnvironment.await(() -> r1().vel() > 250 && r1().x() > x0 + 100, 10_000), "drives: " + r1());
        assertEquals("sent: vel 300 mm/s, rotVel 0 deg/s", onEdt(() -> session.window().statusText()));
        assertTrue(LiveEnvironment.await(() -> onEdt(() -> session.window().readingsText()).contains("vel 300 mm/s"),
                5_000), "the readings show the speed");
        screenshot();
        click("stop");
        assertStops();
        assertEquals("sent: stop", onEdt(() -> session.window().statusText()));
    }

    @Test
    void holdingTheUpArrowDrivesAndReleasingItStops() throws Exception {
        onEdt(() -> {
            session.window().frame().toFront();
            session.window().frame().requestFocus();
            return null;
        });
        // a click on the window's status line gives it the keyboard where no window manager does
        click("status");
        assertTrue(LiveEnvironment.await(() -> onEdt(() -> session.window().frame().isFocused()
                && !(java.awt.KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner()
                        instanceof javax.swing.text.JTextComponent)), 5_000), "the window has the keyboard, not a text field");
        double x0 = r1().x();
        mouse.keyPress(KeyEvent.VK_UP);
        try {
            assertTrue(LiveEnvironment.await(() -> r1().vel() > 250 && r1().x() > x0 + 100, 10_000),
                    "drives while held: " + r1());
        } finally {
            mouse.keyRelease(KeyEvent.VK_UP);
        }
        assertStops();
        assertEquals("sent: stop (keys released)", onEdt(() -> session.window().statusText()));
    }

    @Test
    void theUpArrowInATextFieldMovesTheCaretAndDoesNotDrive() throws Exception {
        click("distance");
        assertTrue(LiveEnvironment.await(() -> onEdt(() -> session.window().find("distance").isFocusOwner()), 5_000),
                "the distance field has the keyboard");
        mouse.keyPress(KeyEvent.VK_UP);
        try {
            assertTrue(env.awaitSteps(5), "held while the run goes on");
        } finally {
            mouse.keyRelease(KeyEvent.VK_UP);
        }
        assertTrue(env.awaitSteps(3), "the run goes on");
        assertEquals(0, r1().vel());
        assertEquals(1500, r1().x(), 1e-6);
    }

    @Test
    void aBadMoveDistanceIsNamedInTheStatusAndSendsNothing() throws Exception {
        onEdt(() -> {
            ((javax.swing.JTextField) session.window().find("distance")).setText("far");
            return null;
        });
        click("move");
        assertTrue(LiveEnvironment.await(() -> onEdt(() -> session.window().statusText()).startsWith("'far' was supplied"),
                5_000));
        assertTrue(env.awaitSteps(3), "the run goes on");
        assertEquals(0, r1().vel());
    }

    @Test
    void atItsDefaultSizeEveryControlShowsWholeAndTheDriveHintReadsAsOneLine() throws Exception {
        // the view's controls wrap onto a second row once the world arrives and the view lays out
        assertTrue(LiveEnvironment.await(() -> onEdt(() -> ((javax.swing.JComboBox<?>) session.window().find("follow"))
                .getItemCount() > 1), 10_000), "the view lists the robots to follow");
        String[] names = {"forward", "back", "left", "right", "stop", "driveHint", "vel", "rotVel", "distance",
            "heading", "move", "sonar", "laser", "status", "3D", "follow", "fit", "showSonar", "showLaser", "showNames",
            "showTrails", "showGrid", "showDrawings"};
        for (String name : names) {
            String hidden = onEdt(() -> {
                Component c = session.window().find(name);
                if (c == null) {
                    return name + ": not in the window";
                }
                Rectangle seen = ((javax.swing.JComponent) c).getVisibleRect();
                return c.isShowing() && c.getWidth() > 0 && seen.width == c.getWidth() && seen.height == c.getHeight()
                        ? null : name + ": " + seen.width + " x " + seen.height + " of " + c.getWidth() + " x "
                        + c.getHeight() + " shows, in a window of " + session.window().frame().getSize();
            });
            assertEquals(null, hidden);
        }
        assertEquals("or hold the arrow keys; space stops",
                onEdt(() -> ((javax.swing.JLabel) session.window().find("driveHint")).getText()));
    }

    /** Saves the window, as on the screen, when {@code robosim.screenshots} names a folder. */
    private void screenshot() throws Exception {
        String folder = System.getProperty("robosim.screenshots");
        if (folder == null || folder.isBlank()) {
            return;
        }
        onEdt(() -> {
            ((javax.swing.JCheckBox) session.window().find("laser")).doClick();
            return null;
        });
        assertTrue(env.awaitSteps(3), "steps with the laser on reach the window");
        mouse.waitForIdle();
        Rectangle bounds = onEdt(() -> session.window().frame().getBounds());
        BufferedImage shot = mouse.createScreenCapture(bounds);
        Path out = Files.createDirectories(Path.of(folder)).resolve("remote-control.png");
        ImageIO.write(shot, "png", out.toFile());
        System.err.println("RemoteWindowTest: saved " + out.toAbsolutePath());
    }
}
