package robosim.env.world;

/**
 * A source of heat in the world (the gold of GoldFinder glows with one).
 *
 * @param x         mm
 * @param y         mm
 * @param intensity its intensity as sensed 1 m away; greater than 0
 * @param line      the line of its element in the world file
 */
public record HeatSource(double x, double y, double intensity, int line) {
}
