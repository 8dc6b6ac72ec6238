package robosim.aria;

/** Where an item goes in a list of callbacks, as ARIA's {@code ArListPos} (ariaTypedefs.h). */
public final class ArListPos {
    private ArListPos() {
    }

    /** ARIA's {@code ArListPos::Pos}. */
    public enum Pos {
        /** first in the list */
        FIRST,
        /** last in the list */
        LAST
    }
}
