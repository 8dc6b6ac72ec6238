/**
 * ARIA's {@code .map} files as read: {@link robosim.map.MapReader} reads one into a
 * {@link robosim.map.MapFile} (its lines, points and cairns, with the line each came from, and the
 * rest of its header in a {@link robosim.map.MapHeader}). Both the Environment, which builds a
 * world of a map, and a robot program's {@code ArMap} read maps through it, so a map means the same
 * to both. Reading is bounded against hostile files: lines of at most 16 KiB, items kept as parsed
 * on primitive arrays ({@link robosim.map.Coordinates}), errors that quote short escaped excerpts,
 * and a heap check before the work ({@code MapMemory}). Every broken rule is a
 * {@link robosim.map.MapFileException} naming the file and the line. The format is described in
 * {@code docs/WORLD-FORMAT.md}.
 */
package robosim.map;
