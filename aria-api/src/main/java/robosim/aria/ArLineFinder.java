package robosim.aria;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;

/**
 * Finds straight lines in a laser's latest scan, as ARIA's {@code ArLineFinder} (ArLineFinder.cpp):
 * the scan's points (readings within 5 m, not ignored, in order of angle) are cut into short lines
 * of at least {@code minLinePoints} points and {@code minLineLen} mm whose ends are close enough for
 * their distance from the laser; neighbouring lines are merged while their angles differ by less
 * than {@code angleTol}, each end lies within {@code linesCloseEnough} of the other's line and the
 * points stay within {@code maxDistFromLine} (average {@code maxAveDistFromLine}) of the merged one;
 * lines of fewer than {@code minPointsInLine} points or shorter than {@code minLineLength} are dropped,
 * and the merging is done again. Points and lines are in global coordinates.
 *
 * <p>It reads {@link ArRangeDevice#getRawReadings()}: in RoboSim, an {@link ArLMS2xx}'s (or
 * {@link ArSick}'s) latest scan. {@link #getPoints()} and {@link #getLines()} give what it found,
 * and {@link #saveLast()} writes them to files as ARIA's does.
 */
public class ArLineFinder {
    private final ArRangeDevice rangeDevice;
    private final double sinMultiplier = Math.sin(Math.toRadians(1)) / Math.sin(Math.toRadians(5));
    private List<ArPose> points = new ArrayList<>();
    private List<ArLineFinderSegment> lines = new ArrayList<>();
    private ArPose poseTaken = new ArPose();
    private boolean flippedFound;
    private boolean flipped;
    private int makingMinLen;
    private int makingMinPoints;
    private int combiningAngleTol;
    private int combiningLinesCloseEnough;
    private int filteringMinPointsInLine;
    private int filteringMinLineLength;
    private int validMaxDistFromLine;
    private int validMaxAveFromLine;
    private int maxDistBetweenPoints;
    private boolean verbose;

    /** @param rangeDevice the laser whose raw readings it reads */
    public ArLineFinder(ArRangeDevice rangeDevice) {
        this.rangeDevice = rangeDevice;
        setLineCreationParams();
        setLineCombiningParams();
        setLineFilteringParams();
        setLineValidParams();
        setMaxDistBetweenPoints();
    }

    /** @return the device it reads */
    public ArRangeDevice getRangeDevice() {
        return rangeDevice;
    }

    /**
     * Reads the latest scan and finds its lines.
     *
     * @return the lines, in scan order (a new list each call)
     */
    public synchronized List<ArLineFinderSegment> getLines() {
        fillPointsFromLaser();
        findLines();
        combineLines();
        filterLines();
        combineLines();
        return Collections.unmodifiableList(new ArrayList<>(lines));
    }

    /** @return the points of the last scan read that are in none of the lines (reads the scan again) */
    public synchronized List<ArPose> getNonLinePoints() {
        getLines();
        boolean[] inLine = new boolean[points.size()];
        for (ArLineFinderSegment s : lines) {
            for (int i = s.getStartPoint(); i <= s.getEndPoint() && i < inLine.length; i++) {
                inLine[i] = true;
            }
        }
        List<ArPose> out = new ArrayList<>();
        for (int i = 0; i < inLine.length; i++) {
            if (!inLine[i]) {
                out.add(points.get(i));
            }
        }
        return out;
    }

    /**
     * Finds the lines in the latest scan and saves them, as ARIA's {@code
     * ArLineFinder::getLinesAndSaveThem} (ArLineFinder.cpp): {@link #getLines()}, then {@link #saveLast()}.
     */
    public synchronized void getLinesAndSaveThem() {
        getLines();
        saveLast();
    }

    /**
     * Writes the points and lines of the last scan read to the files {@code points} ({@code x y} a
     * line) and {@code lines} ({@code x1 y1 dx dy} a line), whole millimetres, in the working
     * directory, as ARIA's {@code ArLineFinder::saveLast} (ArLineFinder.cpp) does; then logs "Saved
     * points and lines". A file that cannot be written is logged, as in ARIA, and nothing more is saved.
     */
    public synchronized void saveLast() {
        if (!write(Path.of("points"), out -> points.forEach(p ->
                out.printf(Locale.ROOT, "%.0f %.0f%n", p.getX(), p.getY())))) {
            return;
        }
        if (!write(Path.of("lines"), out -> lines.forEach(l -> out.printf(Locale.ROOT, "%.0f %.0f %.0f %.0f%n",
                l.getX1(), l.getY1(), l.getX2() - l.getX1(), l.getY2() - l.getY1())))) {
            return;
        }
        ArLog.log(ArLog.Normal, "Saved points and lines");
    }

    private static boolean write(Path file, java.util.function.Consumer<PrintWriter> lines) {
        try (PrintWriter out = new PrintWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8))) {
            lines.accept(out);
            if (out.checkError()) {
                throw new IOException("a write failed");
            }
            return true;
        } catch (IOException e) {
            ArLog.log(ArLog.Terse, "ArLineFinder::log: Could not open '%s' file for output: %s", file,
                    e.getMessage());
            return false;
        }
    }

    /** @return the points of the last scan read, global mm */
    public synchronized List<ArPose> getPoints() {
        return List.copyOf(points);
    }

    /** @return the robot's pose when the last scan read was taken */
    public synchronized ArPose getLinesTakenPose() {
        return new ArPose(poseTaken.getX(), poseTaken.getY(), poseTaken.getTh());
    }

    /** @param verbose whether it logs its steps */
    public synchronized void setVerbose(boolean verbose) {
        this.verbose = verbose;
    }

    /** @return whether it logs its steps */
    public synchronized boolean getVerbose() {
        return verbose;
    }

    /** ARIA's defaults: lines of at least 40 mm and 2 points while cutting. */
    public void setLineCreationParams() {
        setLineCreationParams(40, 2);
    }

    /** @param minLineLen mm @param minLinePoints points; ARIA's defaults 40, 2 */
    public void setLineCreationParams(int minLineLen) {
        setLineCreationParams(minLineLen, 2);
    }

    /**
     * @param minLineLen    a first line's least length, mm
     * @param minLinePoints a first line's least number of points
     */
    public synchronized void setLineCreationParams(int minLineLen, int minLinePoints) {
        makingMinLen = minLineLen;
        makingMinPoints = minLinePoints;
    }

    /** ARIA's defaults: 30 degrees, 75 mm. */
    public void setLineCombiningParams() {
        setLineCombiningParams(30, 75);
    }

    /** @param angleTol degrees; lines close enough: 75 mm */
    public void setLineCombiningParams(int angleTol) {
        setLineCombiningParams(angleTol, 75);
    }

    /**
     * @param angleTol         the largest angle between two lines merged, degrees
     * @param linesCloseEnough the farthest an end may be from the other line, mm
     */
    public synchronized void setLineCombiningParams(int angleTol, int linesCloseEnough) {
        combiningAngleTol = angleTol;
        combiningLinesCloseEnough = linesCloseEnough;
    }

    /** ARIA's defaults: 3 points, 75 mm. */
    public void setLineFilteringParams() {
        setLineFilteringParams(3, 75);
    }

    /** @param minPointsInLine points; least length 75 mm */
    public void setLineFilteringParams(int minPointsInLine) {
        setLineFilteringParams(minPointsInLine, 75);
    }

    /**
     * @param minPointsInLine a kept line's least number of points
     * @param minLineLength   a kept line's least length, mm (more than)
     */
    public synchronized void setLineFilteringParams(int minPointsInLine, int minLineLength) {
        filteringMinPointsInLine = minPointsInLine;
        filteringMinLineLength = minLineLength;
    }

    /** ARIA's defaults: 30 mm, average 20 mm. */
    public void setLineValidParams() {
        setLineValidParams(30, 20);
    }

    /** @param maxDistFromLine mm; average 20 mm */
    public void setLineValidParams(int maxDistFromLine) {
        setLineValidParams(maxDistFromLine, 20);
    }

    /**
     * @param maxDistFromLine    the farthest a merged line's inner point may be from it, mm
     * @param maxAveDistFromLine the largest average distance of its points, mm
     */
    public synchronized void setLineValidParams(int maxDistFromLine, int maxAveDistFromLine) {
        validMaxDistFromLine = maxDistFromLine;
        validMaxAveFromLine = maxAveDistFromLine;
    }

    /** No limit on the distance between neighbouring points of a line (ARIA's default, 0). */
    public void setMaxDistBetweenPoints() {
        setMaxDistBetweenPoints(0);
    }

    /** @param maxDistBetweenPoints the farthest apart two neighbouring points of a line may be, mm; 0 no limit */
    public synchronized void setMaxDistBetweenPoints(int maxDistBetweenPoints) {
        this.maxDistBetweenPoints = maxDistBetweenPoints;
    }

    private void log(String format, Object... args) {
        if (verbose) {
            ArLog.log(ArLog.Normal, "ArLineFinder: " + format, args);
        }
    }

    private void fillPointsFromLaser() {
        points = new ArrayList<>();
        List<ArSensorReading> readings = rangeDevice.getRawReadings();
        if (readings == null || readings.isEmpty()) {
            return;
        }
        if (!flippedFound) {
            int i = Math.min(10, readings.size() / 2);
            flipped = ArMath.subAngle(readings.get(0).getSensorTh(), readings.get(i).getSensorTh()) > 0;
            flippedFound = true;
        }
        poseTaken = readings.get(0).getPoseTaken();
        List<ArSensorReading> ordered = new ArrayList<>(readings);
        if (flipped) {
            Collections.reverse(ordered);
        }
        for (ArSensorReading r : ordered) {
            if (r.getRange() > 5000 || r.getIgnoreThisReading()) {
                continue;
            }
            points.add(r.getPose());
        }
    }

    private double aveDist(ArLineFinderSegment line) {
        double total = 0;
        for (int i = line.getStartPoint(); i <= line.getEndPoint(); i++) {
            total += line.getDistToLine(points.get(i));
        }
        return total / (line.getEndPoint() - line.getStartPoint());
    }

    private void findLines() {
        lines = new ArrayList<>();
        int len = points.size();
        for (int start = 0; start < len; start++) {
            boolean maxDistTriggered = false;
            int end;
            for (end = start; end < len; end++) {
                if (end - start >= makingMinPoints
                        && points.get(start).findDistanceTo(points.get(end)) > makingMinLen) {
                    break;
                }
                if (maxDistBetweenPoints > 0 && end > start
                        && points.get(end - 1).findDistanceTo(points.get(end)) > maxDistBetweenPoints) {
                    maxDistTriggered = true;
                    break;
                }
            }
            if (end >= len || maxDistTriggered) {
                continue;
            }
            ArPose s = points.get(start);
            ArPose e = points.get(end);
            if (s.findDistanceTo(e) < s.findDistanceTo(poseTaken) * sinMultiplier) {
                ArLineFinderSegment line = new ArLineFinderSegment(s.getX(), s.getY(), e.getX(), e.getY(), 1, start,
                        end);
                line.setAveDistFromLine(aveDist(line));
                lines.add(line);
            } else {
                log("too great a distance between points %d and %d", start, end);
            }
        }
    }

    private void combineLines() {
        while (true) {
            List<ArLineFinderSegment> merged = new ArrayList<>();
            int merges = 0;
            int len = lines.size();
            for (int start = 0; start < len; start++) {
                if (start + 1 == len) {
                    merged.add(new ArLineFinderSegment(lines.get(start)));
                    continue;
                }
                ArLineFinderSegment line = averageSegments(lines.get(start), lines.get(start + 1));
                if (line != null) {
                    merged.add(line);
                    merges++;
                    start++; // the next one is merged
                } else {
                    merged.add(new ArLineFinderSegment(lines.get(start)));
                }
            }
            lines = merged;
            if (merges == 0) {
                return;
            }
        }
    }

    private ArLineFinderSegment averageSegments(ArLineFinderSegment line1, ArLineFinderSegment line2) {
        double gap = line1.getEndPoint2().findDistanceTo(line2.getEndPoint1());
        if (maxDistBetweenPoints > 0 && gap > maxDistBetweenPoints) {
            log("not merged: ends %.0f apart, more than the maximum between points", gap);
            return null;
        }
        if (gap > line1.getEndPoint2().findDistanceTo(poseTaken) * sinMultiplier) {
            log("not merged: too great a distance between the two line points");
            return null;
        }
        double angleOff = Math.abs(ArMath.subAngle(line1.getLineAngle(), line2.getLineAngle()));
        if (angleOff > combiningAngleTol) {
            log("not merged: angles %.0f apart", angleOff);
            return null;
        }
        ArPose endPose2 = line2.getEndPoint2();
        ArPose intersection1 = line1.perpPoint(endPose2);
        if (intersection1 == null || intersection1.findDistanceTo(endPose2) > combiningLinesCloseEnough) {
            log("not merged: second line's end too far from the first line");
            return null;
        }
        ArPose endPose1 = line1.getEndPoint1();
        ArPose intersection2 = line2.perpPoint(endPose1);
        if (intersection2 == null || intersection2.findDistanceTo(endPose1) > combiningLinesCloseEnough) {
            log("not merged: first line's end too far from the second line");
            return null;
        }
        int l1C = line1.getNumPoints();
        int l2C = line2.getNumPoints();
        int n = l1C + l2C;
        ArLineFinderSegment line = new ArLineFinderSegment(
                (endPose1.getX() * l1C + intersection2.getX() * l2C) / n,
                (endPose1.getY() * l1C + intersection2.getY() * l2C) / n,
                (endPose2.getX() * l2C + intersection1.getX() * l1C) / n,
                (endPose2.getY() * l2C + intersection1.getY() * l1C) / n,
                n, line1.getStartPoint(), line2.getEndPoint());
        double total = 0;
        for (int i = line.getStartPoint(); i <= line.getEndPoint(); i++) {
            double dist = line.getDistToLine(points.get(i));
            if (dist > validMaxDistFromLine && i != line.getStartPoint() && i != line.getEndPoint()) {
                log("not merged: point %d %.0f from the line (max %d)", i, dist, validMaxDistFromLine);
                return null;
            }
            total += dist;
        }
        line.setAveDistFromLine(total / (line.getEndPoint() - line.getStartPoint()));
        if (line.getAveDistFromLine() > validMaxAveFromLine) {
            log("not merged: average distance from the line %.0f (max %d)", line.getAveDistFromLine(),
                    validMaxAveFromLine);
            return null;
        }
        if (line.getAveDistFromLine() > (line1.getAveDistFromLine() + line2.getAveDistFromLine()) * 1.25) {
            log("not merged: average distance from the line %.2f greater than the two lines' (%.2f, %.2f)",
                    line.getAveDistFromLine(), line1.getAveDistFromLine(), line2.getAveDistFromLine());
            return null;
        }
        if (angleOff < combiningAngleTol / 2) { // ARIA: int / 2
            return line;
        }
        double a = line.getLineAngle();
        if ((ArMath.subAngle(a, line2.getLineAngle()) > 0 && ArMath.subAngle(line1.getLineAngle(), a) > 0)
                || (ArMath.subAngle(a, line1.getLineAngle()) > 0 && ArMath.subAngle(line2.getLineAngle(), a) > 0)) {
            return line;
        }
        log("not merged: the merged line's angle is not between the two");
        return null;
    }

    private void filterLines() {
        List<ArLineFinderSegment> kept = new ArrayList<>();
        for (ArLineFinderSegment l : lines) {
            if (l.getNumPoints() >= filteringMinPointsInLine
                    && l.getEndPoint1().findDistanceTo(l.getEndPoint2()) > filteringMinLineLength) {
                kept.add(new ArLineFinderSegment(l));
            } else {
                log("dropped %s", l);
            }
        }
        lines = kept;
    }
}
