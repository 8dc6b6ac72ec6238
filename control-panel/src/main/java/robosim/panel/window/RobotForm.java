package robosim.panel.window;

import java.awt.FlowLayout;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import java.util.function.Supplier;
import javax.swing.BoxLayout;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import robosim.panel.model.Request;
import robosim.panel.model.RobotLaunch;

/**
 * Adding and placing robots: a program (a class, from RoboSim's classpath or a jar) started under a
 * name, placed at the pose given if any; and the robot selected in the table moved to that pose.
 * Fields in the window rather than dialogs, so the values stay for the next robot.
 */
public final class RobotForm extends JPanel {
    private static final long serialVersionUID = 1L;
    /** The program offered first: the example every world's Pioneer can run. */
    public static final String DEFAULT_PROGRAM = "robosim.examples.wander.Wander";

    final JTextField program = field("program", DEFAULT_PROGRAM, 22);
    final JTextField jar = field("jar", "", 10);
    final JTextField name = field("robotName", "", 8);
    final JTextField x = field("x", "", 6);
    final JTextField y = field("y", "", 6);
    final JTextField th = field("th", "", 4);
    final JButton add = new JButton("Add robot");
    final JButton move = new JButton("Move selected");

    /**
     * @param launches gets each robot to start
     * @param moves    gets the selected robot's move request
     * @param selected the robot selected in the table, or null
     * @param errors   gets what is wrong with a value typed
     */
    public RobotForm(Consumer<RobotLaunch> launches, BiConsumer<String, Request> moves, Supplier<String> selected,
                     Consumer<String> errors) {
        setLayout(new BoxLayout(this, BoxLayout.Y_AXIS));
        add.setName("addRobot");
        move.setName("move");
        add.addActionListener(e -> {
            try {
                launches.accept(RobotLaunch.parse(program.getText(), jar.getText(), name.getText(), x.getText(),
                        y.getText(), th.getText()));
            } catch (IllegalArgumentException ex) {
                errors.accept(ex.getMessage());
            }
        });
        move.addActionListener(e -> {
            String robot = selected.get();
            if (robot == null) {
                errors.accept("Move: select a robot in the table first");
                return;
            }
            try {
                moves.accept(robot, Request.move(robot, x.getText(), y.getText(), th.getText().isBlank() ? "0"
                        : th.getText()));
            } catch (IllegalArgumentException ex) {
                errors.accept(ex.getMessage());
            }
        });
        JPanel launch = new JPanel(new FlowLayout(FlowLayout.LEFT));
        launch.add(new JLabel("Program"));
        launch.add(program);
        launch.add(new JLabel("jar"));
        launch.add(jar);
        launch.add(new JLabel("name"));
        launch.add(name);
        launch.add(add);
        JPanel pose = new JPanel(new FlowLayout(FlowLayout.LEFT));
        pose.add(new JLabel("Pose: x (mm)"));
        pose.add(x);
        pose.add(new JLabel("y (mm)"));
        pose.add(y);
        pose.add(new JLabel("th (deg)"));
        pose.add(th);
        pose.add(move);
        add(launch);
        add(pose);
    }

    private static JTextField field(String fieldName, String text, int columns) {
        JTextField f = new JTextField(text, columns);
        f.setName(fieldName);
        return f;
    }
}
