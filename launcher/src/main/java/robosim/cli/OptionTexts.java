package robosim.cli;

/**
 * What each option name means, written once: an option name used by several commands starts its
 * description with the same text everywhere (the text before the first ';'), so one name has one
 * meaning across {@code robosim}'s commands (CommandLineConsistencyTest checks it).
 */
final class OptionTexts {
    /** {@code --classpath}: where robot programs' classes are. */
    static final String CLASSPATH = "where the robot programs' classes are, besides RoboSim's (directories or jars,"
            + " ':'-separated)";

    static final String ROBOT_PORT = "the robot port";
    static final String VIEWER_PORT = "the viewer port";
    static final String SEED = "the seed of everything random";
    static final String STEPS = "steps to run";
    static final String ROBOTS = "how many robots";
    static final String EVERY = "draw a frame at every K-th step (and the last); default ${DEFAULT-VALUE}";
    /** The default of {@code --every} everywhere: a frame per second of a 50 ms step. */
    static final String EVERY_DEFAULT = "20";
    static final String OUT_DIR = "the folder the run's files go to";
    static final String CELL_SIZE = "the maze's cell size in mm";
    static final String THREADS = "threads that read the robots' sensors each step";
    static final String TOKEN = "the run secret";
    /** --secret-file's meaning, before the semicolon; the commands that take it add their default after it. */
    static final String SECRET_FILE = "read the run secret from FILE (as env --token-file wrote it)";
    static final String WINDOW = "show it in a window";
    static final String PNG_DIR = "write frame-NNNNNN.png files to DIR";
    static final String DRAWINGS = "draw what the robots draw (each one's known map, the frontier it claimed),"
            + " translucent in each robot's colour (2D)";
    /** The hidden old names' descriptions: never shown, kept for scripts written before. */
    static final String OLD_NAME = "old name of ";

    private OptionTexts() {
    }
}
