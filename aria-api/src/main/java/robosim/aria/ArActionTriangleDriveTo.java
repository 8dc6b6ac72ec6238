package robosim.aria;

import java.util.List;

/**
 * Drives up to a triangular target seen by the laser (a docking station's "V"), as ARIA's
 * {@code ArActionTriangleDriveTo} (ArActionTriangleDriveTo.cpp), with an {@link ArLineFinder} on the
 * laser's latest scan. Two consecutive lines about {@code line1Length} and {@code line2Length} long
 * (within 125 mm; ARIA's default 254 mm each), meeting at about {@code angleBetween} (within 15
 * degrees; default 135) with ends at most 100 mm apart, make a vertex: where the two lines cross,
 * facing out along the bisector. Candidates are scored as ARIA scores them (shape first; then, when
 * acquiring, ahead of the robot and on the robot's line; while driving, near the last vertex and its
 * heading) and the best of at least 5 is kept, in encoder coordinates, so it stays put while the
 * robot moves.
 *
 * <p>The states are ARIA's: activated, it <i>acquires</i> (stopped) until it sees the vertex; if it
 * has not for {@code vertexUnseenStopMSecs} (4 s) it <i>searches</i> (turning at
 * {@code acquireTurnSpeed}) when {@link #setAcquire acquiring}, else fails. Seen, it drives to the
 * <i>approach</i> point ({@code approachDistFromVertex} out along the bisector), <i>aligns</i> toward
 * the vertex, then drives to the <i>final</i> point ({@code finalDistFromVertex} out; backwards if
 * it is behind), aligns again and <i>succeeds</i> (held stopped). It skips the approach when it is
 * off to the side or already nearer the final point; with {@link #setGotoVertex} it drives straight
 * at the vertex up to the final distance instead (failing if the vertex is more than 10 degrees off).
 * Lost for too long while driving: searching or failed, as while acquiring. Deactivated: inactive.
 *
 * <p>In RoboSim the laser is the robot's first connected laser ({@link ArRobot#getLaserMap()}), else
 * its range device named "laser" (an {@link ArSick} added as a range device), else the line finder
 * given with {@link #setLineFinder}; with none, activating fails. What it finds is what the
 * simulated laser sees of the world's walls: a target is a V of two walls (or boxes) of the
 * triangle's shape. ARIA's internal {@code Data} (for its debugging displays) is left out.
 */
public class ArActionTriangleDriveTo extends ArAction {
    /** ARIA's states. */
    public enum State {
        /** not trying */
        STATE_INACTIVE,
        /** finding the target */
        STATE_ACQUIRE,
        /** turning to find the target */
        STATE_SEARCHING,
        /** driving to the approach point */
        STATE_GOTO_APPROACH,
        /** aligning to the target the first time */
        STATE_ALIGN_APPROACH,
        /** driving to the vertex */
        STATE_GOTO_VERTEX,
        /** driving to the final point */
        STATE_GOTO_FINAL,
        /** aligning to the target the final time */
        STATE_ALIGN_FINAL,
        /** pointing at the target */
        STATE_SUCCEEDED,
        /** lost the vertex and not acquiring */
        STATE_FAILED
    }

    private final ArActionDesired desired = new ArActionDesired();
    private ArPose vertexEncoder = new ArPose();
    private ArRangeDevice laser;
    private ArLineFinder lineFinder;
    private boolean ownLineFinder;
    private List<ArLineFinderSegment> lines = List.of();
    private long gotLinesCounter = -1;
    private boolean vertexSeen;
    private boolean printing;
    private final ArTime vertexSeenLast = new ArTime();
    private State state = State.STATE_INACTIVE;
    private double originalAngle = 1000;
    private boolean acquire;
    private double finalDistFromVertex;
    private double approachDistFromVertex;
    private double speed;
    private double closeDist;
    private double acquireTurnSpeed;
    private double line1Length;
    private double angleBetween;
    private double line2Length;
    private int vertexUnseenStopMSecs;
    private boolean adjustVertex;
    private boolean gotoVertex;
    private int localXOffset;
    private int localYOffset;
    private double thOffset;
    private boolean useLegacyVertexOffset;
    private double ignoreTriangleDist;
    private boolean useIgnoreInGoto;
    private int maxDistBetweenLinePoints;
    private int maxLateralDist;
    private int maxAngleMisalignment;

    /** ARIA's defaults: "triangleDriveTo", final 400 mm, approach 1000 mm, 200 mm/s, close 100 mm, 30 deg/s. */
    public ArActionTriangleDriveTo() {
        this("triangleDriveTo");
    }

    /** @param name the action's name */
    public ArActionTriangleDriveTo(String name) {
        this(name, 400);
    }

    /** @param name the action's name @param finalDistFromVertex mm */
    public ArActionTriangleDriveTo(String name, double finalDistFromVertex) {
        this(name, finalDistFromVertex, 1000);
    }

    /**
     * @param name                   the action's name
     * @param finalDistFromVertex    where it stops, mm out from the vertex
     * @param approachDistFromVertex where the first stage goes, mm out (0 or less: no first stage)
     */
    public ArActionTriangleDriveTo(String name, double finalDistFromVertex, double approachDistFromVertex) {
        this(name, finalDistFromVertex, approachDistFromVertex, 200);
    }

    /**
     * @param name                   the action's name
     * @param finalDistFromVertex    where it stops, mm out from the vertex
     * @param approachDistFromVertex where the first stage goes, mm out
     * @param speed                  the top speed, mm/s
     */
    public ArActionTriangleDriveTo(String name, double finalDistFromVertex, double approachDistFromVertex,
            double speed) {
        this(name, finalDistFromVertex, approachDistFromVertex, speed, 100);
    }

    /**
     * @param name                   the action's name
     * @param finalDistFromVertex    where it stops, mm out from the vertex
     * @param approachDistFromVertex where the first stage goes, mm out
     * @param speed                  the top speed, mm/s
     * @param closeDist              how close to a point counts as there, mm
     */
    public ArActionTriangleDriveTo(String name, double finalDistFromVertex, double approachDistFromVertex,
            double speed, double closeDist) {
        this(name, finalDistFromVertex, approachDistFromVertex, speed, closeDist, 30);
    }

    /**
     * @param name                   the action's name
     * @param finalDistFromVertex    where it stops, mm out from the vertex
     * @param approachDistFromVertex where the first stage goes, mm out
     * @param speed                  the top speed, mm/s
     * @param closeDist              how close to a point counts as there, mm
     * @param acquireTurnSpeed       the turn while searching, deg/s
     */
    public ArActionTriangleDriveTo(String name, double finalDistFromVertex, double approachDistFromVertex,
            double speed, double closeDist, double acquireTurnSpeed) {
        super(name, "Finds a triangle and drives in front of it");
        setNextArgument(ArArg.ofDouble("final dist from vertex", () -> this.finalDistFromVertex,
                v -> this.finalDistFromVertex = v, "Distance from vertex we want to be at (mm)"));
        setNextArgument(ArArg.ofDouble("approach dist from vertex", () -> this.approachDistFromVertex,
                v -> this.approachDistFromVertex = v,
                "Distance from vertex we'll go to before going to final (0 goes to final) (mm)"));
        setNextArgument(ArArg.ofDouble("speed", () -> this.speed, v -> this.speed = v, "speed to drive at (mm/sec)"));
        setNextArgument(ArArg.ofDouble("close dist", () -> this.closeDist, v -> this.closeDist = v,
                "how close we have to get to our final point (mm)"));
        setNextArgument(ArArg.ofDouble("acquire turn speed", () -> this.acquireTurnSpeed,
                v -> this.acquireTurnSpeed = v, "if we are acquiring the rot vel to turn at (deg/sec)"));
        setParameters(finalDistFromVertex, approachDistFromVertex, speed, closeDist, acquireTurnSpeed);
        setTriangleParams();
        setVertexUnseenStopMSecs();
        setAcquire();
        setIgnoreTriangleDist();
        setMaxDistBetweenLinePoints();
        setMaxLateralDist();
        setMaxAngleMisalignment();
    }

    /**
     * @param finalDistFromVertex    where it stops, mm out from the vertex
     * @param approachDistFromVertex where the first stage goes, mm out
     * @param speed                  the top speed, mm/s
     * @param closeDist              how close to a point counts as there, mm
     * @param acquireTurnSpeed       the turn while searching, deg/s
     */
    public synchronized void setParameters(double finalDistFromVertex, double approachDistFromVertex, double speed,
            double closeDist, double acquireTurnSpeed) {
        this.finalDistFromVertex = finalDistFromVertex;
        this.approachDistFromVertex = approachDistFromVertex;
        this.speed = speed;
        this.closeDist = closeDist;
        this.acquireTurnSpeed = acquireTurnSpeed;
    }

    /** ARIA's defaults (400, 1000, 200, 100, 30). */
    public void setParameters() {
        setParameters(400, 1000, 200, 100, 30);
    }

    /** Not acquiring (ARIA's default for {@code setAcquire()}). */
    public void setAcquire() {
        setAcquire(false);
    }

    /** @param acquire whether it turns to look for the target when it has lost it */
    public synchronized void setAcquire(boolean acquire) {
        this.acquire = acquire;
    }

    /** @return whether it turns to look for the target */
    public synchronized boolean getAcquire() {
        return acquire;
    }

    /** @param dist where it stops, mm out from the vertex */
    public synchronized void setFinalDistFromVertex(double dist) {
        finalDistFromVertex = dist;
    }

    /** @return where it stops, mm out from the vertex */
    public synchronized double getFinalDistFromVertex() {
        return finalDistFromVertex;
    }

    /** ARIA's docking-station target: two 254 mm sides at 135 degrees. */
    public void setTriangleParams() {
        setTriangleParams(254, 135, 254);
    }

    /** @param line1Length mm; ARIA's other defaults */
    public void setTriangleParams(double line1Length) {
        setTriangleParams(line1Length, 135, 254);
    }

    /** @param line1Length mm @param angleBetween degrees; second side 254 mm */
    public void setTriangleParams(double line1Length, double angleBetween) {
        setTriangleParams(line1Length, angleBetween, 254);
    }

    /**
     * @param line1Length  the first side's length, mm (0: any)
     * @param angleBetween the angle inside the V, degrees (0: any; negative: the vertex faces the
     *                     other way, as ARIA's)
     * @param line2Length  the second side's length, mm (0: any)
     */
    public synchronized void setTriangleParams(double line1Length, double angleBetween, double line2Length) {
        this.line1Length = line1Length;
        this.angleBetween = angleBetween;
        this.line2Length = line2Length;
    }

    /** @return whether the vertex is moved to the nearest reading near it */
    public synchronized boolean getAdjustVertex() {
        return adjustVertex;
    }

    /** @param adjustVertex whether the vertex is moved to the nearest laser reading near it */
    public synchronized void setAdjustVertex(boolean adjustVertex) {
        this.adjustVertex = adjustVertex;
    }

    /**
     * @param localXOffset mm along the vertex's heading
     * @param localYOffset mm to its left
     * @param thOffset     degrees
     */
    public synchronized void setVertexOffset(int localXOffset, int localYOffset, double thOffset) {
        this.localXOffset = localXOffset;
        this.localYOffset = localYOffset;
        this.thOffset = thOffset;
    }

    /** @param legacy whether ARIA's old (wrong-signed) vertex offset is used */
    public synchronized void setUseLegacyVertexOffset(boolean legacy) {
        useLegacyVertexOffset = legacy;
    }

    /** @return whether ARIA's old vertex offset is used */
    public synchronized boolean getUseLegacyVertexOffset() {
        return useLegacyVertexOffset;
    }

    /** @return whether it drives straight at the vertex */
    public synchronized boolean getGotoVertex() {
        return gotoVertex;
    }

    /** @param gotoVertex whether it drives straight at the vertex (to the final distance) */
    public synchronized void setGotoVertex(boolean gotoVertex) {
        this.gotoVertex = gotoVertex;
    }

    /** ARIA's default: 250 mm, not in goto-vertex mode. */
    public void setIgnoreTriangleDist() {
        setIgnoreTriangleDist(250, false);
    }

    /** @param dist mm; not in goto-vertex mode */
    public void setIgnoreTriangleDist(double dist) {
        setIgnoreTriangleDist(dist, false);
    }

    /**
     * @param dist                      within this of the final point it stops looking for the
     *                                  triangle (it is too close to see it whole), mm
     * @param useIgnoreInGotoVertexMode whether that holds when driving to the vertex
     */
    public synchronized void setIgnoreTriangleDist(double dist, boolean useIgnoreInGotoVertexMode) {
        ignoreTriangleDist = dist;
        useIgnoreInGoto = useIgnoreInGotoVertexMode;
    }

    /** @return the distance within which it stops looking, mm */
    public synchronized double getIgnoreTriangleDist() {
        return ignoreTriangleDist;
    }

    /** @return whether that holds when driving to the vertex */
    public synchronized boolean getUseIgnoreInGotoVertexMode() {
        return useIgnoreInGoto;
    }

    /** ARIA's default: 4000 ms. */
    public void setVertexUnseenStopMSecs() {
        setVertexUnseenStopMSecs(4000);
    }

    /** @param ms how long it goes on without seeing the vertex */
    public synchronized void setVertexUnseenStopMSecs(int ms) {
        vertexUnseenStopMSecs = ms;
    }

    /** @return how long it goes on without seeing the vertex, ms */
    public synchronized int getVertexUnseenStopMSecs() {
        return vertexUnseenStopMSecs;
    }

    /** No limit (ARIA's default, 0). */
    public void setMaxDistBetweenLinePoints() {
        setMaxDistBetweenLinePoints(0);
    }

    /** @param mm the farthest apart neighbouring points of a line may be (0: no limit) */
    public synchronized void setMaxDistBetweenLinePoints(int mm) {
        maxDistBetweenLinePoints = mm;
    }

    /** No limit (ARIA's default, 0). */
    public void setMaxLateralDist() {
        setMaxLateralDist(0);
    }

    /** @param mm the farthest the vertex may be from the robot's line ahead (0: no limit) */
    public synchronized void setMaxLateralDist(int mm) {
        maxLateralDist = mm;
    }

    /** No limit (ARIA's default, 0). */
    public void setMaxAngleMisalignment() {
        setMaxAngleMisalignment(0);
    }

    /** @param degrees the most the vertex may face away from the robot's heading at activation (0: any) */
    public synchronized void setMaxAngleMisalignment(int degrees) {
        maxAngleMisalignment = degrees;
    }

    /** @return the state */
    public synchronized State getState() {
        return state;
    }

    /** @return whether it has seen the vertex since it was activated (reset when searching) */
    public synchronized boolean getVertexSeen() {
        return vertexSeen;
    }

    /** @return the vertex last found, global coordinates (the origin before any) */
    public synchronized ArPose getVertex() {
        ArRobot robot = myRobot;
        return robot == null ? vertexEncoder : robot.getEncoderTransform().doTransform(vertexEncoder);
    }

    /** @param lineFinder the line finder to use (the action's own is dropped) */
    public synchronized void setLineFinder(ArLineFinder lineFinder) {
        this.lineFinder = lineFinder;
        this.laser = lineFinder == null ? null : lineFinder.getRangeDevice();
        ownLineFinder = false;
    }

    /** @return the line finder it uses, or null */
    public synchronized ArLineFinder getLineFinder() {
        return lineFinder;
    }

    /** @param logging whether it logs its driving */
    public synchronized void setLogging(boolean logging) {
        printing = logging;
    }

    /** @return whether it logs its driving */
    public synchronized boolean getLogging() {
        return printing;
    }

    @Override
    public synchronized void setRobot(ArRobot robot) {
        super.setRobot(robot);
        if (lineFinder == null && robot != null) {
            for (ArLaser l : robot.getLaserMap().values()) {
                if (l.isConnected()) {
                    laser = l;
                    break;
                }
            }
            if (laser == null) {
                laser = robot.findRangeDevice("laser");
            }
            if (laser != null) {
                lineFinder = new ArLineFinder(laser);
                ownLineFinder = true;
            }
        }
    }

    @Override
    public synchronized void activate() {
        super.activate();
        vertexSeen = false;
        vertexSeenLast.setToNow();
        if (lineFinder == null && myRobot != null) {
            setRobot(myRobot);
        }
        if (myRobot == null) {
            return;
        }
        originalAngle = myRobot.getTh();
        state = lineFinder != null ? State.STATE_ACQUIRE : State.STATE_FAILED;
    }

    @Override
    public synchronized void deactivate() {
        super.deactivate();
        state = State.STATE_INACTIVE;
    }

    /** @return whether it made its own line finder (on the robot's laser) */
    synchronized boolean ownsLineFinder() {
        return ownLineFinder;
    }

    private void log(String format, Object... args) {
        if (printing) {
            ArLog.log(ArLog.Normal, "%s: " + format, prepend(getName(), args));
        }
    }

    private static Object[] prepend(Object first, Object[] rest) {
        Object[] all = new Object[rest.length + 1];
        all[0] = first;
        System.arraycopy(rest, 0, all, 1, rest.length);
        return all;
    }

    private ArPose findPoseFromVertex(double distFromVertex) {
        ArPose vertex = myRobot.getEncoderTransform().doTransform(vertexEncoder);
        return new ArPose(vertex.getX() + Math.cos(Math.toRadians(vertex.getTh())) * distFromVertex,
                vertex.getY() + Math.sin(Math.toRadians(vertex.getTh())) * distFromVertex, 0);
    }

    private double findDeltaHeadingTo(ArPose pose) {
        return ArMath.subAngle(myRobot.getPose().findAngleTo(pose), myRobot.getTh());
    }

    private double findDistanceTo(ArPose pose) {
        return myRobot.getPose().findDistanceTo(pose);
    }

    /** The distance from a point to the infinite line from {@code from} along {@code th}. */
    private static double distToRay(ArPose from, double th, ArPose point) {
        ArLineFinderSegment line = new ArLineFinderSegment(from.getX(), from.getY(),
                from.getX() + Math.cos(Math.toRadians(th)) * 20000, from.getY() + Math.sin(Math.toRadians(th)) * 20000);
        return line.getDistToLine(point);
    }

    private void findTriangle(boolean initial, boolean goStraight) {
        if (gotLinesCounter != myRobot.getCounter()) {
            lineFinder.setMaxDistBetweenPoints(maxDistBetweenLinePoints);
            lines = lineFinder.getLines();
        }
        gotLinesCounter = myRobot.getCounter();
        ArPose robotPose = myRobot.getPose();
        ArPose lastVertex = myRobot.getEncoderTransform().doTransform(vertexEncoder);
        double goodLineScore = 0;
        for (int start = 0; start + 1 < lines.size(); start++) {
            ArLineFinderSegment l1 = lines.get(start);
            ArLineFinderSegment l2 = lines.get(start + 1);
            double line1Dist = l1.getEndPoint1().findDistanceTo(l1.getEndPoint2());
            double line2Dist = l2.getEndPoint1().findDistanceTo(l2.getEndPoint2());
            double distLine1ToLine2 = l1.getEndPoint2().findDistanceTo(l2.getEndPoint1());
            double between = ArMath.subAngle(180, ArMath.subAngle(l1.getLineAngle(), l2.getLineAngle()));
            double angleDelta = angleBetween != 0 ? Math.abs(ArMath.subAngle(between, angleBetween)) : 0;
            double line1Delta = line1Length != 0 ? Math.abs(line1Dist - line1Length) : 0;
            double line2Delta = line2Length != 0 ? Math.abs(line2Dist - line2Length) : 0;
            if (line1Delta > 125 || line2Delta > 125 || angleDelta > 15 || distLine1ToLine2 > 100) {
                continue;
            }
            ArPose intersection = l1.lineIntersection(l2);
            if (intersection == null) {
                return; // ARIA's: parallel lines end the search
            }
            double vertexTh = angleBetween > -.1
                    ? ArMath.addAngle(l1.getLineAngle(), between / 2)
                    : ArMath.addAngle(180, ArMath.addAngle(l1.getLineAngle(), between / 2));
            ArPose vertex = new ArPose(intersection.getX(), intersection.getY(), vertexTh);
            if (maxLateralDist > 0 && distToRay(robotPose, robotPose.getTh(), vertex) > maxLateralDist) {
                continue;
            }
            if (maxAngleMisalignment > 0
                    && Math.abs(ArMath.subAngle(ArMath.subAngle(originalAngle, 180), vertex.getTh()))
                            > maxAngleMisalignment) {
                continue;
            }
            ArPose adjustedVertex = null;
            if (adjustVertex && laser != null) {
                ArTransform toLocal = new ArTransform(robotPose, new ArPose());
                ArTransform toGlobal = new ArTransform(new ArPose(), robotPose);
                ArPose end1 = toLocal.doTransform(l1.getEndPoint1());
                ArPose end2 = toLocal.doTransform(l2.getEndPoint2());
                ArPose vertexLocal = toLocal.doTransform(vertex);
                ArPose closest = new ArPose();
                laser.currentReadingBox(vertexLocal.getX() - 100, end1.getY(), Math.max(end1.getX(), end2.getX()),
                        end2.getY(), closest);
                closest = toGlobal.doTransform(closest);
                adjustedVertex = new ArPose(closest.getX(), closest.getY(),
                        ArMath.addAngle(l1.getLineAngle(), between / 2));
            }
            double lineScore = 0;
            lineScore += 10 - line1Delta / 25;
            lineScore += 10 - line2Delta / 25;
            lineScore += 10 - angleDelta / 2;
            if (initial) {
                lineScore *= .5 + .5 * (30 - Math.abs(ArMath.subAngle(robotPose.getTh(),
                        robotPose.findAngleTo(vertex)))) / 30;
                lineScore *= .5 + .5 * (1500 - distToRay(vertex, vertex.getTh(), robotPose)) / 1500;
                lineScore *= .5 + .5 * (30 - Math.abs(ArMath.subAngle(vertex.getTh(), vertex.findAngleTo(robotPose))));
            } else {
                double dist = lastVertex.findDistanceTo(vertex);
                if (dist < 200) {
                    lineScore *= .8;
                } else if (dist < 400) {
                    lineScore *= .5;
                } else if (dist < 600) {
                    lineScore *= .2;
                } else if (dist < 800) {
                    lineScore *= .1;
                } else {
                    lineScore *= 0;
                }
                double angleFromLast = Math.abs(ArMath.subAngle(lastVertex.getTh(), vertex.getTh()));
                if (angleFromLast < 5) {
                    lineScore *= 1;
                } else if (angleFromLast < 10) {
                    lineScore *= .75;
                } else if (angleFromLast < 20) {
                    lineScore *= .5;
                } else if (angleFromLast < 30) {
                    lineScore *= .25;
                } else {
                    lineScore *= 0;
                }
                if (goStraight) {
                    double angle = Math.abs(findDeltaHeadingTo(vertex));
                    if (angle < 2) {
                        lineScore *= 1;
                    } else if (angle < 5) {
                        lineScore *= .5;
                    } else if (angle < 10) {
                        lineScore *= .1;
                    } else {
                        lineScore *= 0;
                    }
                }
            }
            log("vertex (%.0f, %.0f) %.0f score %.2f", vertex.getX(), vertex.getY(), vertex.getTh(), lineScore);
            if (lineScore < 5) {
                continue;
            }
            if (goodLineScore < 1 || lineScore > goodLineScore) {
                goodLineScore = lineScore;
                ArPose used = adjustedVertex != null ? adjustedVertex : vertex;
                if (localXOffset != 0 || localYOffset != 0 || Math.abs(thOffset) > .00001) {
                    ArPose before = used;
                    if (useLegacyVertexOffset) {
                        double c = Math.cos(Math.toRadians(used.getTh()));
                        double s = Math.sin(Math.toRadians(used.getTh()));
                        used = new ArPose(used.getX() + localXOffset * c + localYOffset * s,
                                used.getY() - localXOffset * s - localYOffset * c,
                                ArMath.addAngle(vertex.getTh(), thOffset));
                    } else {
                        ArPose transformed = new ArTransform(before, new ArPose())
                                .doInvTransform(new ArPose(localXOffset, localYOffset, 0));
                        used = new ArPose(transformed.getX(), transformed.getY(),
                                ArMath.addAngle(vertex.getTh(), thOffset));
                    }
                }
                vertexEncoder = myRobot.getEncoderTransform().doInvTransform(used);
                vertexSeen = true;
                vertexSeenLast.setToNow();
            }
        }
    }

    private boolean lostTooLong() {
        return !vertexSeen && vertexSeenLast.mSecSince() > vertexUnseenStopMSecs;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        ArRobot robot = myRobot;
        ArPose vertex = robot.getEncoderTransform().doTransform(vertexEncoder);
        double dist;
        double angle;
        double vel;
        switch (state) {
            case STATE_INACTIVE:
                return null;
            case STATE_SUCCEEDED:
            case STATE_FAILED:
                desired.setVel(0);
                desired.setRotVel(0);
                return desired;
            case STATE_ACQUIRE: {
                findTriangle(true, false);
                if (lostTooLong()) {
                    state = acquire ? State.STATE_SEARCHING : State.STATE_FAILED;
                    log("%s", acquire ? "searching" : "failed: no vertex");
                    return fire(currentDesired);
                }
                if (vertexSeen) {
                    ArPose approach = findPoseFromVertex(approachDistFromVertex);
                    ArPose fin = findPoseFromVertex(finalDistFromVertex);
                    if (approachDistFromVertex <= 0 || Math.abs(findDeltaHeadingTo(approach)) > 90
                            || (Math.abs(findDeltaHeadingTo(approach)) > 45
                                    && findDistanceTo(fin) < findDistanceTo(approach))) {
                        state = gotoVertex ? State.STATE_GOTO_VERTEX : State.STATE_GOTO_FINAL;
                    } else {
                        state = State.STATE_GOTO_APPROACH;
                    }
                    log("vertex seen: %s", state);
                    return fire(currentDesired);
                }
                desired.setVel(0);
                desired.setRotVel(0);
                return desired;
            }
            case STATE_SEARCHING:
                vertexSeen = false;
                findTriangle(true, false);
                if (vertexSeen) {
                    state = State.STATE_ACQUIRE;
                    return fire(currentDesired);
                }
                desired.setVel(0);
                desired.setRotVel(acquireTurnSpeed);
                return desired;
            case STATE_GOTO_APPROACH: {
                findTriangle(false, false);
                if (lostTooLong()) {
                    state = acquire ? State.STATE_SEARCHING : State.STATE_FAILED;
                    return fire(currentDesired);
                }
                ArPose approach = findPoseFromVertex(approachDistFromVertex);
                dist = robot.getPose().findDistanceTo(approach);
                angle = robot.getPose().findAngleTo(approach);
                if (dist < closeDist || (dist < closeDist * 2 && Math.abs(findDeltaHeadingTo(approach)) > 30)) {
                    state = State.STATE_ALIGN_APPROACH;
                    return fire(currentDesired);
                }
                desired.setHeading(angle);
                vel = Math.sqrt(dist * 400 * 2);
                vel *= (180 - Math.abs(findDeltaHeadingTo(approach))) / 180;
                desired.setVel(Math.max(0, Math.min(speed, vel)));
                return desired;
            }
            case STATE_ALIGN_APPROACH:
                angle = robot.getPose().findAngleTo(vertex);
                if (Math.abs(ArMath.subAngle(robot.getTh(), angle)) < 2 && Math.abs(robot.getVel()) < 5) {
                    state = gotoVertex ? State.STATE_GOTO_VERTEX : State.STATE_GOTO_FINAL;
                    return fire(currentDesired);
                }
                desired.setHeading(angle);
                desired.setVel(0);
                return desired;
            case STATE_GOTO_VERTEX: {
                ArPose fin = findPoseFromVertex(0);
                if (useIgnoreInGoto && findDistanceTo(fin) > finalDistFromVertex + ignoreTriangleDist) {
                    findTriangle(false, true);
                }
                if (lostTooLong()) {
                    state = State.STATE_FAILED;
                    return fire(currentDesired);
                }
                fin = findPoseFromVertex(0);
                dist = findDistanceTo(fin) - finalDistFromVertex;
                angle = findDeltaHeadingTo(fin);
                if (Math.abs(angle) > 10) {
                    state = State.STATE_FAILED;
                    return fire(currentDesired);
                }
                desired.setDeltaHeading(angle);
                vel = dist > 0 ? Math.sqrt(dist * 100 * 2) : 0;
                desired.setVel(Math.max(0, Math.min(speed, vel)));
                if (dist <= 0 && Math.abs(robot.getVel()) < 5) {
                    state = State.STATE_SUCCEEDED;
                    return fire(currentDesired);
                }
                return desired;
            }
            case STATE_GOTO_FINAL: {
                ArPose fin = findPoseFromVertex(finalDistFromVertex);
                if (findDistanceTo(fin) > ignoreTriangleDist) {
                    findTriangle(false, false);
                }
                if (lostTooLong()) {
                    state = acquire ? State.STATE_SEARCHING : State.STATE_FAILED;
                    return fire(currentDesired);
                }
                fin = findPoseFromVertex(finalDistFromVertex);
                dist = robot.getPose().findDistanceTo(fin);
                angle = robot.getPose().findAngleTo(fin);
                double delta = findDeltaHeadingTo(fin);
                double v = robot.getVel();
                if (dist < 5 || (v > 0 && dist < closeDist && Math.abs(delta) > 20)
                        || (v < 0 && dist < closeDist && Math.abs(delta) < 160)
                        || (Math.abs(v) < 5 && dist < closeDist)) {
                    state = State.STATE_ALIGN_FINAL;
                    return fire(currentDesired);
                }
                if (Math.abs(ArMath.subAngle(robot.getTh(), angle)) < 90) {
                    desired.setHeading(angle);
                    vel = Math.sqrt(dist * 100 * 2) * (45 - Math.abs(delta)) / 45;
                    desired.setVel(Math.max(0, Math.min(speed, vel)));
                } else {
                    desired.setHeading(ArMath.subAngle(angle, 180));
                    vel = -Math.sqrt(dist * 100 * 2) * (45 - Math.abs(ArMath.subAngle(180, delta))) / 45;
                    desired.setVel(Math.min(0, Math.max(-speed, vel)));
                }
                return desired;
            }
            case STATE_ALIGN_FINAL:
                angle = robot.getPose().findAngleTo(vertex);
                if (Math.abs(ArMath.subAngle(robot.getTh(), angle)) < 2 && Math.abs(robot.getVel()) < 5) {
                    state = State.STATE_SUCCEEDED;
                    return fire(currentDesired);
                }
                desired.setHeading(angle);
                desired.setVel(0);
                return desired;
            default:
                return null;
        }
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
