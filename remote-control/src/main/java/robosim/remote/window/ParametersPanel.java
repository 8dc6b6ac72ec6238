package robosim.remote.window;

import java.awt.BorderLayout;
import java.util.List;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.table.AbstractTableModel;
import robosim.remote.ParameterRows;

/** The robot's parameters, read-only, a row each (see {@link ParameterRows}). */
final class ParametersPanel extends JPanel {
    private static final long serialVersionUID = 1L;

    ParametersPanel(List<ParameterRows.Row> rows) {
        super(new BorderLayout());
        JTable table = new JTable(new Rows(rows));
        table.setName("parameters");
        table.setFillsViewportHeight(true);
        add(new JScrollPane(table), BorderLayout.CENTER);
    }

    /** The rows as an uneditable table model. */
    private static final class Rows extends AbstractTableModel {
        private static final long serialVersionUID = 1L;
        private final List<ParameterRows.Row> rows;

        Rows(List<ParameterRows.Row> rows) {
            this.rows = List.copyOf(rows);
        }

        @Override
        public int getRowCount() {
            return rows.size();
        }

        @Override
        public int getColumnCount() {
            return 2;
        }

        @Override
        public String getColumnName(int column) {
            return column == 0 ? "parameter" : "value";
        }

        @Override
        public Object getValueAt(int row, int column) {
            ParameterRows.Row r = rows.get(row);
            return column == 0 ? r.name() : r.value();
        }
    }
}
