package robosim.remote;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/**
 * The robot's parameters as the parameters panel lists them, read-only: ARIA's parameter-file
 * names ({@code MaxVelocity}, {@code SonarUnit}, ...) with their values and units.
 */
public final class ParameterRows {
    /**
     * One row.
     *
     * @param name  the parameter's name, as in an ARIA {@code .p} file
     * @param value its value, with its unit
     */
    public record Row(String name, String value) { }

    private ParameterRows() {
    }

    /**
     * @param file where the parameters came from (a path, or a shipped name such as {@code p3dx})
     * @param p    the parameters
     * @return the rows, the file first
     */
    public static List<Row> of(String file, RobotParameters p) {
        List<Row> rows = new ArrayList<>();
        rows.add(new Row("file", file));
        rows.add(new Row("Class", p.robotClass()));
        rows.add(new Row("Subclass", p.subclass()));
        rows.add(new Row("Shape", p.shape()));
        rows.add(new Row("RobotRadius", mm(p.robotRadius())));
        rows.add(new Row("RobotWidth", mm(p.robotWidth())));
        rows.add(new Row("RobotLengthFront", mm(p.robotLengthFront())));
        rows.add(new Row("RobotLengthRear", mm(p.robotLengthRear())));
        rows.add(new Row("MaxVelocity", num(p.maxVelocity()) + " mm/s"));
        rows.add(new Row("MaxRVelocity", num(p.maxRVelocity()) + " deg/s"));
        rows.add(new Row("TransAccel", num(p.transAccel()) + " mm/s²"));
        rows.add(new Row("TransDecel", num(p.transDecel()) + " mm/s²"));
        rows.add(new Row("RotAccel", num(p.rotAccel()) + " deg/s²"));
        rows.add(new Row("RotDecel", num(p.rotDecel()) + " deg/s²"));
        rows.add(new Row("DiffConvFactor", num(p.diffConvFactor())));
        rows.add(new Row("SonarMaxRange", mm(p.sonarMaxRange())));
        rows.add(new Row("SonarNum", Integer.toString(p.sonarUnits().size())));
        for (SonarUnit u : p.sonarUnits()) {
            rows.add(new Row("SonarUnit " + u.index(), "x " + mm(u.x()) + ", y " + mm(u.y()) + ", th " + num(u.th()) + "°"));
        }
        rows.add(new Row("LaserX", mm(p.laserX())));
        rows.add(new Row("LaserY", mm(p.laserY())));
        rows.add(new Row("LaserTh", num(p.laserTh()) + "°"));
        rows.add(new Row("LaserMaxRange", mm(p.laserMaxRange())));
        return rows;
    }

    private static String mm(double v) {
        return num(v) + " mm";
    }

    /** Whole numbers without a fraction, others with as many digits as they need (up to 6). */
    private static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return String.format(Locale.ROOT, "%.6f", v).replaceAll("0+$", "");
    }
}
