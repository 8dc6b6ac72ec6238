/**
 * ARIA's {@code .map} files: {@link robosim.env.world.map.MapReader} reads one into a
 * {@link robosim.env.world.map.MapFile} (its lines, points and cairns, with the line each came
 * from), and {@link robosim.env.world.map.MapGeometry} turns that into the world's obstacles,
 * forbidden zones and robot homes. Points that line up are merged into one obstacle
 * ({@code PointMerger} along rows and columns, {@code Staircases} where runs climb like a slanted
 * wall), so that a scanned map of 10^5 points stays quick to
 * load and to sense against. Reading is bounded against hostile files: lines of at most 16 KiB,
 * items kept as parsed on primitive arrays ({@code Coordinates}), errors that quote short escaped
 * excerpts, and a heap check before the work ({@code MapMemory}). The format is described in
 * {@code docs/WORLD-FORMAT.md}.
 */
package robosim.env.world.map;
