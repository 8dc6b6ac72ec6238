package robosim.remote.window;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.Container;
import java.awt.Dimension;
import java.awt.KeyEventDispatcher;
import java.awt.KeyboardFocusManager;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import javax.swing.BorderFactory;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTabbedPane;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.WindowConstants;
import javax.swing.text.JTextComponent;
import robosim.remote.KeyDrive;
import robosim.remote.ParameterRows;
import robosim.remote.RemoteControl;
import robosim.remote.robot.RemoteRobot;
import robosim.viewer.window.ViewModel;
import robosim.viewer.window.ViewState;
import robosim.viewer.window.ViewerPane;

/**
 * The RemoteControl's window: the drive panel and send box on the left, the embedded 2D view
 * following the robot in the middle, the readings and the parameters on the right, and a status
 * line saying what was last sent (or, in red, why not). The arrow keys drive while held, wherever
 * the focus is but in a text field; the space bar stops. Build and use it on the Swing event thread.
 */
public final class RemoteWindow {
    /** How often the readings are redrawn and key releases settled, ms. */
    static final int REFRESH_MS = 50;

    private final JFrame frame;
    private final RemoteControl control;
    private final JLabel status = new JLabel("connected; drive with the buttons or the arrow keys");
    private final ReadingsPanel readings;
    private final Timer timer;
    private final KeyEventDispatcher keys = this::dispatch;
    private final CountDownLatch closed = new CountDownLatch(1);
    private final JPanel content = new JPanel(new BorderLayout(4, 4));
    private boolean endShown;

    /**
     * Builds the window, on the Swing event thread; it shows once {@link #show()} is called.
     *
     * @param robot     the connected robot
     * @param paramFile where its parameters came from, for the parameters panel
     * @param view      the Environment's view fed by a viewer connection, or null for no view
     */
    public RemoteWindow(RemoteRobot robot, String paramFile, ViewModel view) {
        control = new RemoteControl(robot);
        frame = new JFrame("RoboSim remote - " + robot.name());
        frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        DrivePanel.Status lines = new DrivePanel.Status() {
            @Override
            public void sent(String line) {
                if (line != null) {
                    status.setForeground(Color.DARK_GRAY);
                    status.setText(line);
                }
            }

            @Override
            public void error(String message) {
                status.setForeground(Color.RED.darker());
                status.setText(message);
            }
        };
        JPanel left = new JPanel(new BorderLayout());
        left.add(new DrivePanel(control, lines), BorderLayout.NORTH);
        left.add(new MessagePanel(control, lines), BorderLayout.SOUTH);
        readings = new ReadingsPanel(robot);
        JTabbedPane right = new JTabbedPane();
        right.addTab("readings", readings);
        right.addTab("parameters", new ParametersPanel(ParameterRows.of(paramFile, robot.parameters())));
        // the window itself takes the keyboard at first and on a click anywhere off the controls, so the
        // arrow keys drive until a text field is clicked (where they move the caret)
        content.setFocusable(true);
        content.addMouseListener(new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                content.requestFocusInWindow();
            }
        });
        content.add(left, BorderLayout.WEST);
        content.add(view == null ? new JLabel("no view: the Environment's viewer port was not reached", JLabel.CENTER)
                : followingView(view, robot.name()), BorderLayout.CENTER);
        content.add(right, BorderLayout.EAST);
        status.setName("status");
        status.setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        content.add(status, BorderLayout.SOUTH);
        frame.setContentPane(content);
        timer = new Timer(REFRESH_MS, e -> {
            lines.sent(control.tick(System.currentTimeMillis()));
            readings.refresh();
            if (robot.runEnd() != null && !endShown) {
                endShown = true;
                lines.error(robot.runEnd().describe());
            }
        });
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowDeactivated(WindowEvent e) {
                lines.sent(control.keysLost());
            }

            @Override
            public void windowClosed(WindowEvent e) {
                timer.stop();
                KeyboardFocusManager.getCurrentKeyboardFocusManager().removeKeyEventDispatcher(keys);
                closed.countDown();
            }
        });
    }

    private static ViewerPane followingView(ViewModel model, String robot) {
        ViewState state = new ViewState();
        state.setFollow(robot);
        ViewerPane pane = new ViewerPane(model, state);
        pane.setPreferredSize(new Dimension(560, 560));
        return pane;
    }

    /** Shows the window and starts taking keys and refreshing the readings. */
    public void show() {
        KeyboardFocusManager.getCurrentKeyboardFocusManager().addKeyEventDispatcher(keys);
        timer.start();
        frame.pack();
        frame.setLocationByPlatform(true);
        frame.setVisible(true);
        content.requestFocusInWindow();
    }

    /** The arrow keys and the space bar, for this window, unless a text field is typing. */
    private boolean dispatch(KeyEvent e) {
        Component c = e.getComponent();
        Object owner = KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner();
        if (c == null || SwingUtilities.getWindowAncestor(c) != frame && c != frame || owner instanceof JTextComponent) {
            return false;
        }
        KeyDrive.Key key = switch (e.getKeyCode()) {
            case KeyEvent.VK_UP, KeyEvent.VK_KP_UP -> KeyDrive.Key.FORWARD;
            case KeyEvent.VK_DOWN, KeyEvent.VK_KP_DOWN -> KeyDrive.Key.BACK;
            case KeyEvent.VK_LEFT, KeyEvent.VK_KP_LEFT -> KeyDrive.Key.LEFT;
            case KeyEvent.VK_RIGHT, KeyEvent.VK_KP_RIGHT -> KeyDrive.Key.RIGHT;
            default -> null;
        };
        long now = System.currentTimeMillis();
        if (key != null && e.getID() == KeyEvent.KEY_PRESSED) {
            status(control.keyPressed(key, now));
        } else if (key != null && e.getID() == KeyEvent.KEY_RELEASED) {
            control.keyReleased(key, now);
        } else if (e.getKeyCode() == KeyEvent.VK_SPACE && e.getID() == KeyEvent.KEY_PRESSED) {
            status(control.button(RemoteControl.Button.STOP));
        } else {
            return false;
        }
        return true;
    }

    private void status(String line) {
        if (line != null) {
            status.setForeground(Color.DARK_GRAY);
            status.setText(line);
        }
    }

    /** @return the window's frame */
    public JFrame frame() {
        return frame;
    }

    /**
     * @param name a component's name ({@code forward}, {@code stop}, {@code distance}, {@code sonar}, ...)
     * @return the first component of that name in the window, or null
     */
    public Component find(String name) {
        return find(frame.getContentPane(), name);
    }

    private static Component find(Container in, String name) {
        for (Component c : in.getComponents()) {
            if (name.equals(c.getName())) {
                return c;
            }
            if (c instanceof Container inner) {
                Component found = find(inner, name);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }

    /** @return the status line's text */
    public String statusText() {
        return status.getText();
    }

    /** @return the readings panel's lines, as shown */
    public String readingsText() {
        return readings.readingsText();
    }

    /** Closes the window (as the user does). */
    public void close() {
        frame.dispose();
    }

    /**
     * Waits until the window is closed.
     *
     * @param timeoutMs the longest wait, ms; 0 or less waits without limit
     * @return whether it closed
     * @throws InterruptedException if interrupted
     */
    public boolean awaitClosed(long timeoutMs) throws InterruptedException {
        if (timeoutMs <= 0) {
            closed.await();
            return true;
        }
        return closed.await(timeoutMs, TimeUnit.MILLISECONDS);
    }
}
