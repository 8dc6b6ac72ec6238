package robosim.env.world.xml;

/**
 * An element of a world file as Jackson reads it: attribute values as raw text, checked and
 * converted later, and the line it starts on, set by {@link LocatingDeserializer}.
 */
abstract class Element {
    private int line;

    /** @return the element's name in the file, for messages */
    abstract String tag();

    /** @return the 1-based line the element starts on */
    final int line() {
        return line;
    }

    final void locate(int line) {
        this.line = line;
    }
}
