package robosim.pioneer;

/** A packet's data does not hold what its ID says it should: too short, or a field out of range. */
public class PacketFormatException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /**
     * @param message what was wrong, naming the packet and the field
     */
    public PacketFormatException(String message) {
        super(message);
    }
}
