package robosim.viewer.window;

import java.awt.FlowLayout;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.function.Function;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import robosim.protocol.WorldDescription;
import robosim.viewer.draw.RenderOptions;
import robosim.viewer.draw.Trails;

/**
 * The toolbar of display choices: sonar rays, laser scans, names, trails, the grid and the robots'
 * drawings (2D only) shown or hidden, the 2D or the 3D view, the robot to follow, and a button that fits the whole world back in view.
 */
public final class DisplayControls extends JPanel {
    private static final long serialVersionUID = 1L;
    /** The follow choice that follows no robot. */
    public static final String NOBODY = "(none)";

    private final transient ViewModel model;
    private final transient ViewState state;
    private final WorldView view;
    private final JComboBox<String> follow = new JComboBox<>();
    private final List<JCheckBox> toggles = new ArrayList<>();
    private transient WorldDescription listed;
    private boolean updating;

    /**
     * @param model what the window shows
     * @param state how it shows it
     * @param view  the drawing area to repaint
     */
    public DisplayControls(ViewModel model, ViewState state, WorldView view) {
        super(new WrapLayout(FlowLayout.LEFT, 6, 2));
        this.model = model;
        this.state = state;
        this.view = view;
        RenderOptions r = state.render();
        toggle("Sonar", r.showSonar(), (o, on) -> o.withSonar(on));
        toggle("Laser", r.showLaser(), (o, on) -> o.withLaser(on));
        toggle("Names", r.showNames(), (o, on) -> o.withNames(on));
        toggle("Trails", r.showTrails(), (o, on) -> o.withTrails(on));
        toggle("Grid", r.showGrid(), (o, on) -> o.withGrid(on));
        toggle("Drawings", r.showDrawings(), (o, on) -> o.withDrawings(on));
        JCheckBox threeD = new JCheckBox("3D", state.threeD());
        threeD.setName("3D");
        threeD.addActionListener(e -> {
            state.setThreeD(threeD.isSelected());
            view.repaint();
        });
        toggles.add(threeD);
        add(threeD);
        follow.addItem(NOBODY);
        follow.addActionListener(e -> {
            if (!updating) {
                Object chosen = follow.getSelectedItem();
                state.setFollow(chosen == null || NOBODY.equals(chosen) ? null : chosen.toString());
                view.repaint();
            }
        });
        follow.setName("follow");
        // the label and its list wrap onto a new row together
        JPanel following = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        following.add(new JLabel("Follow:"));
        following.add(follow);
        add(following);
        JButton fit = new JButton("Fit");
        fit.setName("fit");
        fit.addActionListener(e -> {
            state.fit();
            view.repaint();
        });
        add(fit);
        model.observe(this::refresh);
        view.addPropertyChangeListener("view", e -> refresh());
    }

    /** A toggle of one drawing option. */
    @FunctionalInterface
    private interface Change {
        RenderOptions apply(RenderOptions options, boolean on);
    }

    private void toggle(String label, boolean on, Change change) {
        JCheckBox box = new JCheckBox(label, on);
        box.setName("show" + label);
        box.addActionListener(e -> {
            state.setRender(change.apply(state.render(), box.isSelected()));
            view.repaint();
        });
        toggles.add(box);
        add(box);
    }

    /** Lists the world's robots to follow, and shows whom the view follows now. */
    private void refresh() {
        updating = true;
        try {
            WorldDescription world = model.world();
            if (world != null && world != listed) {
                listed = world;
                follow.removeAllItems();
                follow.addItem(NOBODY);
                world.robots().forEach(r -> follow.addItem(r.name()));
            }
            String current = state.follow() == null ? NOBODY : state.follow();
            if (!Objects.equals(follow.getSelectedItem(), current)) {
                follow.setSelectedItem(current);
            }
        } finally {
            updating = false;
        }
    }

    /**
     * Finds a check box by its label, for tests and for keyboard shortcuts.
     *
     * @param label the label, such as {@code "Sonar"}
     * @return the check box
     * @throws IllegalArgumentException if there is none
     */
    public JCheckBox toggle(String label) {
        return find(toggles, JCheckBox::getText, label);
    }

    /** @return the follow chooser */
    public JComboBox<String> followChooser() {
        return follow;
    }

    private static <T> T find(List<T> items, Function<T, String> name, String wanted) {
        return items.stream().filter(i -> name.apply(i).equals(wanted)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no control labelled '" + wanted + "'"));
    }
}
