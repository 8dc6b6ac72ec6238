package robosim.panel.window;

import java.awt.FlowLayout;
import java.util.Hashtable;
import java.util.function.Consumer;
import javax.swing.BoxLayout;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.JTextField;
import robosim.panel.model.Pace;
import robosim.panel.model.Request;
import robosim.panel.model.RobotRows;
import robosim.protocol.RunStatus;

/**
 * The run's buttons (pause, resume, step N, stop, restart), the pacing slider and the run's line
 * (world, step, paused or running, pace). Each button hands its {@link Request} to a sink; a value
 * typed wrong is reported to the error sink instead, and nothing is sent.
 */
public final class RunControls extends JPanel {
    private static final long serialVersionUID = 1L;

    final JButton pause = button("Pause", "pause");
    final JButton resume = button("Resume", "resume");
    final JButton step = button("Step", "step");
    final JTextField steps = new JTextField("1", 5);
    final JButton stop = button("Stop", "stop");
    final JButton restart = button("Restart", "restart");
    final JSlider pace = new JSlider(0, Pace.MAX, Pace.MAX);
    private final JLabel line = new JLabel("not attached");
    private boolean showing;

    /**
     * @param requests gets each request a button or the slider makes
     * @param errors   gets what is wrong with a value typed
     * @param restarts called when Restart is pressed
     */
    public RunControls(Consumer<Request> requests, Consumer<String> errors, Runnable restarts) {
        setLayout(new BoxLayout(this, BoxLayout.Y_AXIS));
        steps.setName("steps");
        pace.setName("pace");
        line.setName("runLine");
        Hashtable<Integer, JComponent> labels = new Hashtable<>();
        for (int i = 0; i < Pace.STOPS.size(); i++) {
            labels.put(i, new JLabel(Pace.STOPS.get(i).label()));
        }
        pace.setLabelTable(labels);
        pace.setPaintLabels(true);
        pace.setSnapToTicks(true);
        pace.setMajorTickSpacing(1);
        // wide enough that the stops' labels do not overlap
        pace.setPreferredSize(new java.awt.Dimension(420, pace.getPreferredSize().height));
        pace.addChangeListener(e -> {
            // only the user's settled choice is sent: not each stop passed while dragging, nor a status shown
            if (!showing && !pace.getValueIsAdjusting()) {
                requests.accept(Request.pace(Pace.STOPS.get(pace.getValue())));
            }
        });
        pause.addActionListener(e -> requests.accept(Request.pause()));
        resume.addActionListener(e -> requests.accept(Request.resume()));
        stop.addActionListener(e -> requests.accept(Request.stop()));
        restart.addActionListener(e -> restarts.run());
        step.addActionListener(e -> {
            try {
                requests.accept(Request.step(steps.getText()));
            } catch (IllegalArgumentException x) {
                errors.accept(x.getMessage());
            }
        });
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.LEFT));
        for (JComponent c : new JComponent[] {pause, resume, step, steps, stop, restart, new JLabel("Pace:"), pace}) {
            buttons.add(c);
        }
        JPanel status = new JPanel(new FlowLayout(FlowLayout.LEFT));
        status.add(line);
        add(buttons);
        add(status);
    }

    private static JButton button(String text, String name) {
        JButton b = new JButton(text);
        b.setName(name);
        return b;
    }

    /**
     * Shows a status: the run's line, and the pace in force on the slider unless the user holds it.
     *
     * @param status the run's status
     */
    public void show(RunStatus status) {
        line.setText(RobotRows.runLine(status));
        if (!pace.getValueIsAdjusting()) {
            showing = true;
            try {
                pace.setValue(Pace.nearest(status.pace()));
            } finally {
                showing = false;
            }
        }
    }

    /**
     * @param text what to show in the run's line when there is no status (not attached, or lost)
     */
    public void showLine(String text) {
        line.setText(text);
    }

    /** @return the run's line as shown */
    public String line() {
        return line.getText();
    }
}
