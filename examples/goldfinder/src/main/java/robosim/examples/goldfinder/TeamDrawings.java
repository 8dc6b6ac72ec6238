package robosim.examples.goldfinder;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import robosim.aria.ArRobot;
import robosim.protocol.Figure;

/**
 * What a Gold robot draws of what it believes, for the viewers (with {@code --drawings}), so that a
 * user sees how the team divides the maze: three layers, in the robot's own colour. The static
 * methods make each layer's figures; {@link #update} sends a layer again when it has changed, at
 * most every {@value #DRAW_EVERY} steps.
 */
final class TeamDrawings {
    /** The cells the robot sensed itself: its share of the work, filled. */
    static final String EXPLORED = "explored";
    /** Every cell the robot knows of, its own and its teammates' reports: a dot each. */
    static final String KNOWN = "known";
    /** The frontier it claimed (a square) or follows (a smaller square), with its way there. */
    static final String CLAIM = "claim";
    /** The fewest steps between two drawings. */
    static final int DRAW_EVERY = 10;

    private final ArRobot robot;
    private final int rank;
    private final double cellSize;
    private final MazeKnowledge map;
    private final List<int[]> ownCells;
    private final Course course;
    /** When it last drew, and what: its own cells' count, the known cells' count, its target and its cell then. */
    private long drawnAt = Long.MIN_VALUE / 2;
    private int drawnCells;
    private int drawnKnown;
    private long drawnTarget = -1;
    private long drawnFrom = -1;

    /**
     * @param robot    the robot that draws
     * @param rank     its number, which places its dots
     * @param cellSize the maze's cell size, mm
     * @param map      what it knows
     * @param ownCells the cells it sensed itself, in order
     * @param course   where it is and its plan
     */
    TeamDrawings(ArRobot robot, int rank, double cellSize, MazeKnowledge map, List<int[]> ownCells, Course course) {
        this.robot = robot;
        this.rank = rank;
        this.cellSize = cellSize;
        this.map = map;
        this.ownCells = ownCells;
        this.course = course;
    }

    /**
     * Draws again each layer that changed since it was last drawn, unless the last drawing is
     * fewer than {@value #DRAW_EVERY} steps old.
     */
    void update() {
        if (robot.getStep() - drawnAt < DRAW_EVERY) {
            return;
        }
        if (ownCells.size() != drawnCells) {
            drawnCells = ownCells.size();
            robot.draw(EXPLORED, explored(ownCells, cellSize));
            drawnAt = robot.getStep();
        }
        if (map.sensedCount() != drawnKnown) {
            // what teammates told counts too: each robot's known map shows what reached it
            drawnKnown = map.sensedCount();
            robot.draw(KNOWN, known(map, rank, cellSize));
            drawnAt = robot.getStep();
        }
        long target = course.plan().target();
        if (target != drawnTarget || (target >= 0 && course.here() != drawnFrom)) {
            drawnTarget = target;
            drawnFrom = course.here();
            robot.draw(CLAIM, claim(map, course.x(), course.y(), course.plan(), cellSize));
            drawnAt = robot.getStep();
        }
    }

    /**
     * @param ownCells the cells the robot sensed itself: column, row, open sides
     * @param cellSize mm
     * @return one figure of the cells, inset an eighth of a cell so the walls stay clear; none if it sensed none
     */
    static List<Figure> explored(List<int[]> ownCells, double cellSize) {
        if (ownCells.isEmpty()) {
            return List.of();
        }
        double inset = cellSize * 0.12;
        double[] xy = new double[4 * ownCells.size()];
        for (int i = 0; i < ownCells.size(); i++) {
            double x0 = ownCells.get(i)[0] * cellSize;
            double y0 = ownCells.get(i)[1] * cellSize;
            xy[4 * i] = x0 + inset;
            xy[4 * i + 1] = y0 + inset;
            xy[4 * i + 2] = x0 + cellSize - inset;
            xy[4 * i + 3] = y0 + cellSize - inset;
        }
        return List.of(new Figure(Figure.CELLS, "", xy));
    }

    /**
     * @param map      what the robot knows
     * @param rank     its number: each robot's dots sit a little apart, so every robot's map shows
     * @param cellSize mm
     * @return one figure of dots, one per known cell, near its centre; none if it knows none
     */
    static List<Figure> known(MazeKnowledge map, int rank, double cellSize) {
        if (map.sensedCount() == 0) {
            return List.of();
        }
        double dx = cellSize * (0.1 * (rank % 4) - 0.15);
        double dy = cellSize * (0.1 * (rank / 4 % 4) - 0.15);
        double[] xy = new double[2 * map.sensedCount()];
        int i = 0;
        for (long k : map.sensedCells()) {
            xy[i++] = (MazeKnowledge.keyX(k) + 0.5) * cellSize + dx;
            xy[i++] = (MazeKnowledge.keyY(k) + 0.5) * cellSize + dy;
        }
        return List.of(new Figure(Figure.DOTS, "", xy));
    }

    /**
     * @param map      what the robot knows
     * @param x        the robot's cell's column
     * @param y        its row
     * @param plan     the frontier it claimed or follows
     * @param cellSize mm
     * @return the frontier as a square (a smaller one when only followed) and the known way there
     *         as a line through the cells' centres; none without a plan
     */
    static List<Figure> claim(MazeKnowledge map, int x, int y, TeamPlan.Plan plan, double cellSize) {
        if (plan.target() < 0) {
            return List.of();
        }
        List<Figure> figures = new ArrayList<>();
        double x0 = plan.x() * cellSize;
        double y0 = plan.y() * cellSize;
        double in = cellSize * (plan.claim() ? 0.3 : 0.4);
        figures.add(new Figure(Figure.CELLS, "", new double[] {x0 + in, y0 + in, x0 + cellSize - in, y0 + cellSize - in}));
        List<Long> way = map.path(x, y, plan.x(), plan.y(), new int[] {0, 1, 2, 3}, Set.of());
        if (!way.isEmpty()) {
            double[] line = new double[2 * (way.size() + 1)];
            line[0] = (x + 0.5) * cellSize;
            line[1] = (y + 0.5) * cellSize;
            for (int k = 0; k < way.size(); k++) {
                line[2 * k + 2] = (MazeKnowledge.keyX(way.get(k)) + 0.5) * cellSize;
                line[2 * k + 3] = (MazeKnowledge.keyY(way.get(k)) + 0.5) * cellSize;
            }
            figures.add(new Figure(Figure.LINE, "", line));
        }
        return figures;
    }
}
