package robosim.panel.window;

import java.awt.BorderLayout;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import javax.swing.BoxLayout;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.JSplitPane;
import javax.swing.WindowConstants;
import robosim.panel.model.Request;
import robosim.panel.model.RunSettings;
import robosim.protocol.RunStatus;
import robosim.viewer.window.ViewModel;
import robosim.viewer.window.ViewState;
import robosim.viewer.window.ViewerPane;

/**
 * The ControlPanel: where the run comes from ({@link RunForm}), the run's buttons and pace
 * ({@link RunControls}), the live view (viewer2d's {@link ViewerPane}, 2D or 3D), the robots'
 * table with its actions ({@link RobotTable}, {@link RobotForm}) and the log ({@link LogPane}).
 * Closing it stops every JVM it started. Made and used on the event thread.
 */
public final class ControlPanelWindow extends JFrame {
    private static final long serialVersionUID = 1L;

    private final transient PanelController controller;
    private final transient CountDownLatch closed = new CountDownLatch(1);
    private final LogPane log = new LogPane();
    private final RunControls controls;
    private final RobotTable robots = new RobotTable();
    private final ViewerPane view;

    /**
     * @param worlds   the worlds to offer (the shipped ones)
     * @param selected the world to select, or null
     */
    public ControlPanelWindow(List<Path> worlds, Path selected) {
        super("RoboSim ControlPanel");
        ViewModel model = new ViewModel();
        view = new ViewerPane(model, new ViewState());
        // a method reference, not a lambda: the controls are made after the controller
        controller = new PanelController(model, log::append, this::showStatus, this::showLine);
        RunForm form = new RunForm(worlds, selected, controller::start,
                a -> controller.attach(a.host(), a.viewerPort(), a.robotPort(), null), this::error);
        controls = new RunControls(controller::send, this::error, controller::restart);
        RobotForm robotForm = new RobotForm(controller::addRobot, (robot, r) -> controller.send(r), robots::selected,
                this::error);
        form.load.addActionListener(e -> {
            try {
                controller.send(Request.load(String.valueOf(form.world.getSelectedItem())));
            } catch (IllegalArgumentException x) {
                error(x.getMessage());
            }
        });
        robots.remove.addActionListener(e -> {
            String r = robots.selected();
            if (r == null) {
                error("Remove: select a robot in the table first");
            } else {
                controller.send(Request.remove(r));
            }
        });
        robots.remote.addActionListener(e -> {
            String r = robots.selected();
            if (r == null) {
                error("Open RemoteControl: select a robot in the table first");
            } else {
                controller.openRemote(r);
            }
        });
        JPanel north = new JPanel();
        north.setLayout(new BoxLayout(north, BoxLayout.Y_AXIS));
        north.add(form);
        north.add(controls);
        north.add(new CommsForm(controller::comms, this::error));
        JPanel table = new JPanel(new BorderLayout());
        table.add(robots, BorderLayout.CENTER);
        table.add(robotForm, BorderLayout.SOUTH);
        JSplitPane right = new JSplitPane(JSplitPane.VERTICAL_SPLIT, table, log);
        right.setResizeWeight(0.6);
        JSplitPane center = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, view, right);
        center.setResizeWeight(0.4);
        center.setDividerLocation(640);
        getContentPane().add(north, BorderLayout.NORTH);
        getContentPane().add(center, BorderLayout.CENTER);
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                // stopping the JVMs the panel started may take seconds: not on the event thread
                Thread t = new Thread(() -> {
                    controller.close();
                    closed.countDown();
                }, "panel-close");
                t.start();
            }
        });
        setSize(1600, 1000);
    }

    private void showStatus(RunStatus status) {
        robots.show(status);
        controls.show(status);
    }

    private void showLine(String line) {
        controls.showLine(line);
    }

    private void error(String message) {
        log.append("panel: " + message);
        controls.showLine(message);
    }

    /**
     * Starts a new run as if the user pressed Start with these settings.
     *
     * @param settings the run's settings
     */
    public void start(RunSettings settings) {
        controller.start(settings);
    }

    /**
     * Attaches as if the user pressed Attach.
     *
     * @param host       the Environment's host
     * @param viewerPort its viewer port
     * @param robotPort  its robot port, 0 if not known (robots cannot be added then)
     * @param token      the run secret, or null to find it as every client does
     */
    public void attach(String host, int viewerPort, int robotPort, String token) {
        controller.attach(host, viewerPort, robotPort, token);
    }

    /**
     * Waits until the window is closed and everything it started is stopped.
     *
     * @throws InterruptedException if interrupted while waiting
     */
    public void awaitClosed() throws InterruptedException {
        closed.await();
    }

    /** @return the run's buttons, for tests */
    public RunControls controls() {
        return controls;
    }

    /** @return the robots' table, for tests */
    public RobotTable robots() {
        return robots;
    }

    /** @return the log, for tests */
    public LogPane log() {
        return log;
    }

    /** @return the live view */
    public ViewerPane view() {
        return view;
    }
}
