/**
 * Reading world files: the XML description of a world, read by
 * {@link robosim.env.world.xml.WorldReader} into the immutable {@link robosim.env.world.World}.
 *
 * <p>Reading is strict. Every broken rule is reported as one
 * {@link robosim.env.world.xml.WorldFileException} whose message names the file, the 1-based line of
 * the offending element and the rule, so that a world can be fixed without a debugger. The format
 * is described in {@code docs/WORLD-FORMAT.md}.
 *
 * <p>The XML is read by Jackson into mutable element classes private to this package, then
 * checked and converted; nothing outside the package sees them.
 */
package robosim.env.world.xml;
