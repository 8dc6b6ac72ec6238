package robosim.panel.window;

import java.awt.FlowLayout;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import java.util.stream.Stream;
import javax.swing.BoxLayout;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import robosim.panel.model.RunSettings;

/**
 * Where a run comes from: a new Environment (a world chosen from the shipped ones or a file, the
 * seed, the ports and the address to listen on), or one already running (host and ports).
 */
public final class RunForm extends JPanel {
    private static final long serialVersionUID = 1L;

    final JComboBox<String> world = new JComboBox<>();
    final JTextField seed = field("seed", "1", 6);
    final JTextField robotPort = field("robotPort", "0", 5);
    final JTextField viewerPort = field("viewerPort", "0", 5);
    final JTextField bind = field("bind", "127.0.0.1", 9);
    final JButton start = new JButton("Start");
    /** Loads the world chosen into the Environment attached to, in place of its run. */
    final JButton load = new JButton("Load into run");
    final JTextField host = field("host", "127.0.0.1", 9);
    final JTextField attachPort = field("attachPort", "", 5);
    final JTextField attachRobotPort = field("attachRobotPort", "", 5);
    final JButton attach = new JButton("Attach");

    /** What the user asked for: attach to host, viewer port and robot port (0 when not given). */
    record Attach(String host, int viewerPort, int robotPort) { }

    /**
     * @param worlds   the world files to offer first (the shipped ones), and the one to select, if any
     * @param selected the world to select, or null
     * @param starts   gets the settings of a new run when Start is pressed
     * @param attaches gets where to attach when Attach is pressed
     * @param errors   gets what is wrong with a value typed
     */
    public RunForm(List<Path> worlds, Path selected, Consumer<RunSettings> starts, Consumer<Attach> attaches,
                   Consumer<String> errors) {
        setLayout(new BoxLayout(this, BoxLayout.Y_AXIS));
        world.setName("world");
        world.setEditable(true);
        worlds.forEach(w -> world.addItem(w.toString()));
        if (selected != null) {
            world.setSelectedItem(selected.toString());
        }
        start.setName("start");
        load.setName("load");
        load.setToolTipText("run the world chosen in the Environment attached to, in place of its run");
        attach.setName("attach");
        JButton browse = new JButton("Browse...");
        browse.addActionListener(e -> {
            JFileChooser chooser = new JFileChooser(worlds.isEmpty() ? null : worlds.get(0).getParent().toFile());
            if (chooser.showOpenDialog(this) == JFileChooser.APPROVE_OPTION) {
                world.setSelectedItem(chooser.getSelectedFile().getPath());
            }
        });
        start.addActionListener(e -> {
            try {
                starts.accept(RunSettings.parse(String.valueOf(world.getSelectedItem()), seed.getText(),
                        robotPort.getText(), viewerPort.getText(), bind.getText()));
            } catch (IllegalArgumentException x) {
                errors.accept(x.getMessage());
            }
        });
        attach.addActionListener(e -> {
            try {
                attaches.accept(new Attach(host.getText().trim(), port("Viewer port", attachPort.getText(), false),
                        port("Robot port", attachRobotPort.getText(), true)));
            } catch (IllegalArgumentException x) {
                errors.accept(x.getMessage());
            }
        });
        JPanel run = new JPanel(new FlowLayout(FlowLayout.LEFT));
        run.add(new JLabel("New run: world"));
        run.add(world);
        run.add(browse);
        run.add(new JLabel("seed"));
        run.add(seed);
        run.add(new JLabel("robot port"));
        run.add(robotPort);
        run.add(new JLabel("viewer port"));
        run.add(viewerPort);
        run.add(new JLabel("bind"));
        run.add(bind);
        run.add(start);
        run.add(load);
        JPanel running = new JPanel(new FlowLayout(FlowLayout.LEFT));
        running.add(new JLabel("Or attach to a running Environment: host"));
        running.add(host);
        running.add(new JLabel("viewer port"));
        running.add(attachPort);
        running.add(new JLabel("robot port (to add robots)"));
        running.add(attachRobotPort);
        running.add(attach);
        add(run);
        add(running);
    }

    private static JTextField field(String name, String text, int columns) {
        JTextField f = new JTextField(text, columns);
        f.setName(name);
        return f;
    }

    private static int port(String field, String text, boolean optional) {
        if (optional && text.isBlank()) {
            return 0;
        }
        try {
            int p = Integer.parseInt(text.trim());
            if (p >= 1 && p <= 65535) {
                return p;
            }
        } catch (NumberFormatException e) {
            // reported below with the rule
        }
        throw new IllegalArgumentException(field + ": a port from 1 to 65535, got '" + text + "'");
    }

    /**
     * @param folder a folder of worlds, or null
     * @return its world files (.xml, .map), sorted; none when it is missing
     */
    public static List<Path> worldsIn(Path folder) {
        if (folder == null || !Files.isDirectory(folder)) {
            return List.of();
        }
        try (Stream<Path> s = Files.list(folder)) {
            return s.filter(p -> p.toString().endsWith(".xml") || p.toString().endsWith(".map")).sorted().toList();
        } catch (IOException e) {
            return List.of();
        }
    }
}
