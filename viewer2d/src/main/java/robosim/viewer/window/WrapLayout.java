package robosim.viewer.window;

import java.awt.Component;
import java.awt.Container;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Insets;

/**
 * A {@link FlowLayout} whose preferred height counts the rows it wraps onto, so that a row of
 * controls placed where only its preferred height is given (the north of a border layout) shows
 * every control when it is narrower than the row, instead of hiding the ones that wrapped.
 */
final class WrapLayout extends FlowLayout {
    private static final long serialVersionUID = 1L;

    WrapLayout(int align, int hgap, int vgap) {
        super(align, hgap, vgap);
    }

    @Override
    public Dimension preferredLayoutSize(Container target) {
        return size(target, true);
    }

    @Override
    public Dimension minimumLayoutSize(Container target) {
        Dimension d = size(target, false);
        d.width -= getHgap() + 1;
        return d;
    }

    /** The size when the controls wrap at the width the target has, or would have, in its parent. */
    private Dimension size(Container target, boolean preferred) {
        synchronized (target.getTreeLock()) {
            Container sized = target;
            while (sized.getSize().width == 0 && sized.getParent() != null) {
                sized = sized.getParent();
            }
            int width = sized.getSize().width == 0 ? Integer.MAX_VALUE : sized.getSize().width;
            Insets insets = target.getInsets();
            int room = width - insets.left - insets.right - 2 * getHgap();
            int rowWidth = 0;
            int rowHeight = 0;
            int widest = 0;
            int height = 0;
            for (Component c : target.getComponents()) {
                if (!c.isVisible()) {
                    continue;
                }
                Dimension d = preferred ? c.getPreferredSize() : c.getMinimumSize();
                if (rowWidth > 0 && rowWidth + getHgap() + d.width > room) {
                    widest = Math.max(widest, rowWidth);
                    height += rowHeight + getVgap();
                    rowWidth = 0;
                    rowHeight = 0;
                }
                rowWidth += (rowWidth > 0 ? getHgap() : 0) + d.width;
                rowHeight = Math.max(rowHeight, d.height);
            }
            widest = Math.max(widest, rowWidth);
            height += rowHeight;
            return new Dimension(widest + insets.left + insets.right + 2 * getHgap(),
                    height + insets.top + insets.bottom + 2 * getVgap());
        }
    }
}
