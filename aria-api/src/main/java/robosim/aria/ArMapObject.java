package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import robosim.map.Cairn;

/**
 * ARIA's {@code ArMapObject} (ArMapObject.h, ArMapObject.cpp): a point or region of interest of a
 * map, read from its {@code Cairn:} line: a {@code Goal} or {@code GoalWithHeading}, a
 * {@code Dock}, a {@code RobotHome}, a {@code ForbiddenLine}, a {@code ForbiddenArea}, or any type
 * a map names. A line or an area has from and to points ({@link #hasFromTo()}); an area's corners
 * are those points turned by the pose's heading about the map's origin
 * ({@link #getFromToSegments()}, {@link #getRegionVertices()}), as ARIA's {@code setFromTo} turns
 * them. Immutable: ARIA's setters that change a map's objects are not kept.
 */
public final class ArMapObject {
    private static final String WITH_HEADING = "WithHeading";

    private final String type;
    private final String baseType;
    private final String name;
    private final String description;
    private final ArPose pose;
    private final String iconName;
    private final boolean hasFromTo;
    private final ArPose fromPose;
    private final ArPose toPose;
    private final List<ArLineSegment> fromToSegments = new ArrayList<>();
    private final ArLineSegment fromToSegment;

    /**
     * A map object, as ARIA's constructor.
     *
     * @param type        its type, for example {@code Goal} or {@code ForbiddenArea}
     * @param pose        its pose: mm, mm, degrees
     * @param description its description, or null for none
     * @param iconName    its icon ({@code ICON}, or {@code ID=n}), or null for none
     * @param name        its name, or null for none
     * @param hasFromTo   whether it is a line or an area
     * @param fromPose    its from point when {@code hasFromTo}
     * @param toPose      its to point when {@code hasFromTo}
     */
    public ArMapObject(String type, ArPose pose, String description, String iconName, String name,
                       boolean hasFromTo, ArPose fromPose, ArPose toPose) {
        this.type = type != null ? type : "";
        this.name = name != null ? name : "";
        this.description = description != null ? description : "";
        this.pose = new ArPose(pose);
        this.iconName = iconName != null ? iconName : "";
        this.hasFromTo = hasFromTo;
        this.fromPose = new ArPose(fromPose);
        this.toPose = new ArPose(toPose);
        this.fromToSegment = new ArLineSegment(fromPose, toPose);
        if (hasFromTo) {
            List<ArPose> corners = getRegionVertices();
            for (int i = 0; i < corners.size(); i++) {
                fromToSegments.add(new ArLineSegment(corners.get(i), corners.get((i + 1) % corners.size())));
            }
            baseType = this.type;
        } else {
            boolean withHeading = this.type.endsWith(WITH_HEADING) && this.type.length() > WITH_HEADING.length();
            baseType = withHeading ? this.type.substring(0, this.type.length() - WITH_HEADING.length()) : this.type;
        }
    }

    /**
     * @param cairn a cairn as the map reader read it
     * @return it as a map object, as ARIA's {@code createMapObject} makes one of the same line
     */
    static ArMapObject of(Cairn cairn) {
        double[] ft = cairn.fromTo();
        boolean fromTo = ft.length == 4;
        return new ArMapObject(cairn.type(), new ArPose(cairn.x(), cairn.y(), cairn.th()), cairn.description(),
                cairn.icon(), cairn.label(), fromTo, fromTo ? new ArPose(ft[0], ft[1]) : new ArPose(),
                fromTo ? new ArPose(ft[2], ft[3]) : new ArPose());
    }

    /** @return its type, as the map writes it */
    public String getType() {
        return type;
    }

    /** @return its type without a trailing {@code WithHeading} ({@code GoalWithHeading} gives {@code Goal}); lines and areas keep theirs */
    public String getBaseType() {
        return baseType;
    }

    /** @return its name, or an empty string */
    public String getName() {
        return name;
    }

    /** @return its description, or an empty string */
    public String getDescription() {
        return description;
    }

    /** @return its description: ARIA keeps {@code getFileName} for old programs and answers the description */
    public String getFileName() {
        return description;
    }

    /** @return its icon ({@code ICON} on most maps) */
    public String getIconName() {
        return iconName;
    }

    /** @return the number after {@code ID=} in its icon, or 0 (ARIA's {@code getId}) */
    public int getId() {
        if (!iconName.startsWith("ID=")) {
            return 0;
        }
        int end = 3;
        if (end < iconName.length() && (iconName.charAt(end) == '-' || iconName.charAt(end) == '+')) {
            end++;
        }
        while (end < iconName.length() && Character.isDigit(iconName.charAt(end))) {
            end++;
        }
        try {
            return Integer.parseInt(iconName.substring(3, end)); // as atoi: the leading digits
        } catch (NumberFormatException e) {
            return 0;
        }
    }

    /** @return a copy of its pose; for a line or an area, its heading is the area's rotation */
    public ArPose getPose() {
        return new ArPose(pose);
    }

    /** @return whether it is a line or an area, with from and to points */
    public boolean hasFromTo() {
        return hasFromTo;
    }

    /** @return a copy of its from point, as written (not turned); (0, 0) when it has none */
    public ArPose getFromPose() {
        return new ArPose(fromPose);
    }

    /** @return a copy of its to point, as written (not turned); (0, 0) when it has none */
    public ArPose getToPose() {
        return new ArPose(toPose);
    }

    /** @return the heading its area is turned by, degrees; 0 for an object without from and to points */
    public double getFromToRotation() {
        return hasFromTo ? pose.getTh() : 0;
    }

    /**
     * The four sides of its area, as ARIA's {@code getFromToSegments}: the rectangle with corners
     * (fx, fy), (tx, fy), (tx, ty), (fx, ty), each turned by the pose's heading about the map's
     * origin, in that order.
     *
     * @return new segments; empty for an object without from and to points
     */
    public List<ArLineSegment> getFromToSegments() {
        List<ArLineSegment> copy = new ArrayList<>();
        for (ArLineSegment s : fromToSegments) {
            copy.add(new ArLineSegment(s.getX1(), s.getY1(), s.getX2(), s.getY2()));
        }
        return copy;
    }

    /** @return a new segment from its from point to its to point, as written: a forbidden line's line */
    public ArLineSegment getFromToSegment() {
        return new ArLineSegment(fromToSegment.getX1(), fromToSegment.getY1(), fromToSegment.getX2(),
                fromToSegment.getY2());
    }

    /** @return the corners of its area, turned, in the order of {@link #getFromToSegments()}; empty without from and to points */
    public List<ArPose> getRegionVertices() {
        List<ArPose> v = new ArrayList<>();
        if (!hasFromTo) {
            return v;
        }
        double sa = ArMath.sin(pose.getTh());
        double ca = ArMath.cos(pose.getTh());
        double fx = fromPose.getX();
        double fy = fromPose.getY();
        double tx = toPose.getX();
        double ty = toPose.getY();
        v.add(new ArPose(fx * ca - fy * sa, fx * sa + fy * ca));
        v.add(new ArPose(tx * ca - fy * sa, tx * sa + fy * ca));
        v.add(new ArPose(tx * ca - ty * sa, tx * sa + ty * ca));
        v.add(new ArPose(fx * ca - ty * sa, fx * sa + ty * ca));
        return v;
    }

    /** @return its pose, or for a line or an area the middle of its from and to points, turned (ARIA's {@code findCenter}) */
    public ArPose findCenter() {
        if (!hasFromTo) {
            return new ArPose(pose);
        }
        double cx = (fromPose.getX() + toPose.getX()) / 2.0;
        double cy = (fromPose.getY() + toPose.getY()) / 2.0;
        double sa = ArMath.sin(pose.getTh());
        double ca = ArMath.cos(pose.getTh());
        return new ArPose(cx * ca - cy * sa, cx * sa + cy * ca);
    }

    /** Logs it as its {@code Cairn:} line (ARIA's {@code log}). */
    public void log() {
        ArLog.log(ArLog.Terse, "Cairn: %s", this);
    }

    /**
     * @return its {@code Cairn:} line without the {@code Cairn:}, as ARIA's {@code toString} writes
     *         it: {@code Type x y th "description" icon "name" [fx fy tx ty]}, x and y and the
     *         points in whole mm, th with six decimals
     */
    @Override
    public String toString() {
        String s = String.format(Locale.ROOT, "%s %.0f %.0f %f \"%s\" %s \"%s\"", type, pose.getX(), pose.getY(),
                pose.getTh(), description, iconName, name);
        if (hasFromTo) {
            s += String.format(Locale.ROOT, " %.0f %.0f %.0f %.0f", fromPose.getX(), fromPose.getY(), toPose.getX(),
                    toPose.getY());
        }
        return s;
    }
}
