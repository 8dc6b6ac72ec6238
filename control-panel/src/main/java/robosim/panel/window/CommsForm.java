package robosim.panel.window;

import java.awt.FlowLayout;
import java.util.function.Consumer;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import robosim.panel.model.CommsChange;
import robosim.protocol.CommsUpdate;

/** The comms settings of the run (range, walls, latency, loss, size), changed while it runs; an empty field keeps its value. */
public final class CommsForm extends JPanel {
    private static final long serialVersionUID = 1L;

    final JTextField range = field("commsRange", 6);
    final JComboBox<String> walls = new JComboBox<>(new String[] {"", "yes", "no"});
    final JTextField latency = field("commsLatency", 4);
    final JTextField loss = field("commsLoss", 4);
    final JTextField maxBytes = field("commsMaxBytes", 6);
    final JButton apply = new JButton("Apply comms");

    /**
     * @param changes gets each change to send
     * @param errors  gets what is wrong with a value typed
     */
    public CommsForm(Consumer<CommsUpdate> changes, Consumer<String> errors) {
        super(new FlowLayout(FlowLayout.LEFT));
        walls.setName("commsWalls");
        apply.setName("applyComms");
        apply.addActionListener(e -> {
            try {
                changes.accept(CommsChange.parse(range.getText(), String.valueOf(walls.getSelectedItem()),
                        latency.getText(), loss.getText(), maxBytes.getText()));
            } catch (IllegalArgumentException x) {
                errors.accept(x.getMessage());
            }
        });
        add(new JLabel("Comms: range (mm, 0 none)"));
        add(range);
        add(new JLabel("walls block"));
        add(walls);
        add(new JLabel("latency (steps)"));
        add(latency);
        add(new JLabel("loss (0-1)"));
        add(loss);
        add(new JLabel("max bytes"));
        add(maxBytes);
        add(apply);
    }

    private static JTextField field(String name, int columns) {
        JTextField f = new JTextField(columns);
        f.setName(name);
        return f;
    }
}
