/**
 * ARIA's {@code .map} files as worlds: {@link robosim.env.world.map.MapGeometry} turns what
 * {@code robosim.map.MapReader} read (a {@code robosim.map.MapFile}) into the world's obstacles,
 * forbidden zones and robot homes. Points that line up are merged into one obstacle
 * ({@code PointMerger} along rows and columns, {@code Staircases} where runs climb like a slanted
 * wall), so that a scanned map of 10^5 points stays quick to load and to sense against. The format
 * is described in {@code docs/WORLD-FORMAT.md}.
 */
package robosim.env.world.map;
