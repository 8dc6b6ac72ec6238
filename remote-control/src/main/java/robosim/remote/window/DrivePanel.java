package robosim.remote.window;

import java.awt.BorderLayout;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.GridLayout;
import java.awt.Insets;
import java.util.function.Function;
import java.util.function.Supplier;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.JTextField;
import robosim.remote.RemoteControl;
import robosim.remote.SpeedLimits;

/**
 * The drive controls: the five buttons, the speed sliders within the robot's limits, the move and
 * heading fields, and the sonar, laser and heat switches. Each hands its action to the
 * {@link RemoteControl} and what comes back to the status line.
 */
final class DrivePanel extends JPanel {
    private static final long serialVersionUID = 1L;

    private final transient RemoteControl control;
    private final transient Status status;
    private final JTextField distance = new JTextField("1000", 6);
    private final JTextField heading = new JTextField("90", 6);

    /** Where an action's outcome goes. */
    interface Status {
        /** @param line what was sent, or null when nothing was */
        void sent(String line);

        /** @param message why nothing was sent */
        void error(String message);
    }

    DrivePanel(RemoteControl control, Status status) {
        super(new BorderLayout(0, 8));
        this.control = control;
        this.status = status;
        setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        add(buttons(), BorderLayout.NORTH);
        add(sliders(), BorderLayout.CENTER);
        JPanel south = new JPanel(new BorderLayout(0, 8));
        south.add(fields(), BorderLayout.NORTH);
        south.add(sensors(), BorderLayout.SOUTH);
        add(south, BorderLayout.SOUTH);
    }

    private JPanel buttons() {
        JPanel grid = new JPanel(new GridLayout(3, 3, 4, 4));
        grid.add(new JLabel());
        grid.add(button("Forward", "forward", RemoteControl.Button.FORWARD));
        grid.add(new JLabel());
        grid.add(button("Left", "left", RemoteControl.Button.LEFT));
        grid.add(button("Stop", "stop", RemoteControl.Button.STOP));
        grid.add(button("Right", "right", RemoteControl.Button.RIGHT));
        grid.add(new JLabel());
        grid.add(button("Back", "back", RemoteControl.Button.BACK));
        grid.add(new JLabel());
        // one line under the buttons, so that it reads whole: not cut into the grid's cells
        JLabel hint = new JLabel(hint(control.keydrive()), JLabel.CENTER);
        hint.setName("driveHint");
        JPanel drive = new JPanel(new BorderLayout(0, 4));
        drive.add(grid, BorderLayout.CENTER);
        drive.add(hint, BorderLayout.SOUTH);
        drive.setBorder(BorderFactory.createTitledBorder("drive"));
        return drive;
    }

    /**
     * @param keydrive whether the keys feed ARIA's keydrive action
     * @return the drive hint: with keydrive each press steps the action, else the keys drive while held
     */
    static String hint(boolean keydrive) {
        return keydrive ? "or press the arrow keys (keydrive); space stops" : "or hold the arrow keys; space stops";
    }

    private JButton button(String text, String name, RemoteControl.Button which) {
        JButton b = new JButton(text);
        b.setName(name);
        // the arrow keys drive: a button must not keep the focus and take the space bar as a click
        b.setFocusable(false);
        b.addActionListener(e -> status.sent(control.button(which)));
        return b;
    }

    private JPanel sliders() {
        SpeedLimits limits = control.limits();
        JPanel p = new JPanel(new GridLayout(4, 1));
        p.setBorder(BorderFactory.createTitledBorder("speeds"));
        JLabel velLabel = new JLabel();
        JLabel rotLabel = new JLabel();
        JSlider vel = slider("vel", limits.maxVel(), control.vel(), velLabel, "translational %d of %d mm/s",
                v -> control.setVel(v));
        JSlider rot = slider("rotVel", limits.maxRotVel(), control.rotVel(), rotLabel, "rotational %d of %d deg/s",
                v -> control.setRotVel(v));
        p.add(velLabel);
        p.add(vel);
        p.add(rotLabel);
        p.add(rot);
        return p;
    }

    private JSlider slider(String name, int max, int value, JLabel label, String format,
                           Function<Integer, String> onChange) {
        JSlider s = new JSlider(0, Math.max(max, 1), Math.min(value, Math.max(max, 1)));
        s.setName(name);
        s.setFocusable(false);
        label.setText(String.format(format, s.getValue(), max));
        s.addChangeListener(e -> {
            label.setText(String.format(format, s.getValue(), max));
            if (!s.getValueIsAdjusting()) {
                status.sent(onChange.apply(s.getValue()));
            }
        });
        return s;
    }

    private JPanel fields() {
        JPanel p = new JPanel(new GridBagLayout());
        p.setBorder(BorderFactory.createTitledBorder("move and turn"));
        distance.setName("distance");
        heading.setName("heading");
        row(p, 0, "distance (mm)", distance, action("Move", "move", () -> control.move(distance.getText())));
        row(p, 1, "heading (deg)", heading, action("Turn to", "turn", () -> control.heading(heading.getText())));
        distance.addActionListener(e -> act(() -> control.move(distance.getText())));
        heading.addActionListener(e -> act(() -> control.heading(heading.getText())));
        return p;
    }

    private static void row(JPanel p, int y, String label, JComponent field, JComponent button) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridy = y;
        c.insets = new Insets(2, 2, 2, 2);
        c.anchor = GridBagConstraints.WEST;
        p.add(new JLabel(label), c);
        c.fill = GridBagConstraints.HORIZONTAL;
        c.weightx = 1;
        p.add(field, c);
        c.weightx = 0;
        p.add(button, c);
    }

    private JButton action(String text, String name, Supplier<String> action) {
        JButton b = new JButton(text);
        b.setName(name);
        b.setFocusable(false);
        b.addActionListener(e -> act(action));
        return b;
    }

    private void act(Supplier<String> action) {
        try {
            status.sent(action.get());
        } catch (IllegalArgumentException e) {
            status.error(e.getMessage());
        }
    }

    private JPanel sensors() {
        JPanel p = new JPanel(new GridLayout(1, 3));
        p.setBorder(BorderFactory.createTitledBorder("sensors"));
        p.add(toggle("sonar", true, on -> control.sonar(on)));
        p.add(toggle("laser", false, on -> control.laser(on)));
        p.add(toggle("heat", false, on -> control.heat(on)));
        return p;
    }

    private JCheckBox toggle(String name, boolean on, Function<Boolean, String> onChange) {
        JCheckBox box = new JCheckBox(name, on);
        box.setName(name);
        box.setFocusable(false);
        box.addActionListener(e -> {
            String line = onChange.apply(box.isSelected());
            if (line.startsWith("sent:")) {
                status.sent(line);
            } else {
                // the robot has no such sensor: the switch goes back off
                box.setSelected(false);
                status.error(line);
            }
        });
        return box;
    }
}
