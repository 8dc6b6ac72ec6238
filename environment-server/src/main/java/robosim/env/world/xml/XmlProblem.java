package robosim.env.world.xml;

/**
 * A broken rule found while Jackson reads the elements, where the file is not known. Jackson may
 * wrap it; {@link ElementReader} finds it in the cause chain and names the file.
 */
final class XmlProblem extends RuntimeException {
    private static final long serialVersionUID = 1L;

    final int line;
    final String rule;

    XmlProblem(int line, String rule) {
        super(line + ": " + rule);
        this.line = line;
        this.rule = rule;
    }
}
