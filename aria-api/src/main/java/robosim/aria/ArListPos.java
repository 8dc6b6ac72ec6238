package robosim.aria;

/**
 * ARIA's {@code ArListPos}: where in a callback list a callback goes, first or last (ariaUtil.h,
 * where {@code FIRST} is 1 and {@code LAST} 2). {@link ArRobot}'s connection callbacks take it.
 */
public final class ArListPos {
    /** Put the callback first in the list. */
    public static final int FIRST = 1;
    /** Put the callback last in the list. */
    public static final int LAST = 2;

    private ArListPos() {
    }
}
