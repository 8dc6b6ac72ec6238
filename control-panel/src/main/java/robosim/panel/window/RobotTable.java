package robosim.panel.window;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JButton;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.ListSelectionModel;
import javax.swing.table.AbstractTableModel;
import robosim.panel.model.RobotRows;
import robosim.panel.model.SeenRobots;
import robosim.protocol.RunStatus;

/**
 * The live table of robots, one row per robot of the last status ({@link RobotRows}), with the
 * actions on the robot selected: remove it, open a RemoteControl on it.
 */
public final class RobotTable extends JPanel {
    private static final long serialVersionUID = 1L;

    private final transient SeenRobots seen = new SeenRobots();
    private final Rows rows = new Rows();
    private final JTable table = new JTable(rows);
    final JButton remove = button("Remove", "remove");
    final JButton remote = button("Open RemoteControl", "remote");

    /** An empty table. */
    public RobotTable() {
        super(new BorderLayout());
        table.setName("robots");
        table.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        table.setAutoCreateRowSorter(false);
        // every column readable at once; the table scrolls sideways when the pane is narrow
        table.setAutoResizeMode(JTable.AUTO_RESIZE_OFF);
        int[] widths = {70, 70, 170, 120, 130, 60, 70, 50, 70, 70, 130};
        for (int i = 0; i < widths.length; i++) {
            table.getColumnModel().getColumn(i).setPreferredWidth(widths[i]);
        }
        add(new JScrollPane(table), BorderLayout.CENTER);
        JPanel actions = new JPanel(new FlowLayout(FlowLayout.LEFT));
        actions.add(remove);
        actions.add(remote);
        add(actions, BorderLayout.SOUTH);
    }

    private static JButton button(String text, String name) {
        JButton b = new JButton(text);
        b.setName(name);
        return b;
    }

    /**
     * Shows a status, keeping the robot selected selected.
     *
     * @param status the run's status
     */
    public void show(RunStatus status) {
        String selected = selected();
        rows.set(RobotRows.of(status, seen.update(status)));
        if (selected != null) {
            select(selected);
        }
    }

    /** @return the name of the robot selected, or null */
    public String selected() {
        int i = table.getSelectedRow();
        return i < 0 || i >= rows.data.size() ? null : rows.data.get(i).get(RobotRows.NAME);
    }

    /**
     * @param name a robot's name
     * @return whether a row shows it, and it is now selected
     */
    public boolean select(String name) {
        for (int i = 0; i < rows.data.size(); i++) {
            if (rows.data.get(i).get(RobotRows.NAME).equals(name)) {
                table.setRowSelectionInterval(i, i);
                return true;
            }
        }
        return false;
    }

    /** @return the table, for tests and screenshots */
    public JTable table() {
        return table;
    }

    /** The rows as a Swing table reads them. */
    private static final class Rows extends AbstractTableModel {
        private static final long serialVersionUID = 1L;
        private List<List<String>> data = new ArrayList<>();

        void set(List<List<String>> newRows) {
            boolean sameShape = newRows.size() == data.size();
            data = newRows;
            if (sameShape) {
                // an update of the cells keeps the user's selection and scroll position
                fireTableRowsUpdated(0, Math.max(0, data.size() - 1));
            } else {
                fireTableDataChanged();
            }
        }

        @Override
        public int getRowCount() {
            return data.size();
        }

        @Override
        public int getColumnCount() {
            return RobotRows.COLUMNS.size();
        }

        @Override
        public String getColumnName(int column) {
            return RobotRows.COLUMNS.get(column);
        }

        @Override
        public Object getValueAt(int row, int column) {
            return data.get(row).get(column);
        }
    }
}
