package robosim.protocol;

/**
 * The bumper ring's part of a robot's state: its contacts.
 *
 * @param sectors bit i set when the body touches something in sector i of {@value #SECTORS}, sector
 *                0 centred dead ahead, counting counter-clockwise
 */
public record Bumpers(int sectors) {
    /** The bumper ring's sectors, 60° each. */
    public static final int SECTORS = 6;

    /** No contact. */
    public static final Bumpers NONE = new Bumpers(0);

    /** Its key: absent reads as {@link #NONE}. */
    public static final StatePart<Bumpers> PART = new StatePart<>("bumpers", Bumpers.class, NONE);

    /** Checks the bits name sectors. */
    public Bumpers {
        if (sectors < 0 || sectors >= 1 << SECTORS) {
            throw new IllegalArgumentException(sectors + " was supplied for the bumper contacts: bits of "
                    + SECTORS + " sectors, 0 to " + ((1 << SECTORS) - 1));
        }
    }
}
