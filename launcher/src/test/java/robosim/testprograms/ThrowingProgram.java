package robosim.testprograms;

import java.io.IOException;

/**
 * A robot program whose {@code main} fails before it connects, as a student's first program might:
 * an {@link IllegalStateException} "boom" thrown two calls down, caused by an {@link IOException}.
 * The tests look for its frames, with file and line, in what {@code robosim robot} prints.
 */
public final class ThrowingProgram {
    private ThrowingProgram() {
    }

    public static void main(String[] args) {
        drive(args[0]);
    }

    static void drive(String robot) {
        try {
            readMap(robot);
        } catch (IOException e) {
            throw new IllegalStateException("boom", e);
        }
    }

    static void readMap(String robot) throws IOException {
        throw new IOException("no map for robot " + robot);
    }
}
