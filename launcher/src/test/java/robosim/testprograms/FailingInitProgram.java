package robosim.testprograms;

/** A robot program whose class fails as it is initialized: its static initializer throws. */
public final class FailingInitProgram {
    static final int SPEED = Integer.parseInt("fast");

    private FailingInitProgram() {
    }

    public static void main(String[] args) {
        System.out.println(SPEED);
    }
}
