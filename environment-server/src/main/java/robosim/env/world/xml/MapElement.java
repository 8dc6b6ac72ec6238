package robosim.env.world.xml;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;

/** A {@code <map>} element: an ARIA map file whose walls, points and cairns the world takes in. */
final class MapElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String file;

    @Override
    String tag() {
        return "map";
    }
}
