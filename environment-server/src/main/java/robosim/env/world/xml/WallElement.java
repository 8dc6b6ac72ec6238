package robosim.env.world.xml;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;

/** A {@code <wall>} element: a segment with a thickness and a height. */
final class WallElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String x1;
    @JacksonXmlProperty(isAttribute = true)
    String y1;
    @JacksonXmlProperty(isAttribute = true)
    String x2;
    @JacksonXmlProperty(isAttribute = true)
    String y2;
    @JacksonXmlProperty(isAttribute = true)
    String thickness;
    @JacksonXmlProperty(isAttribute = true)
    String height;
    @JacksonXmlProperty(isAttribute = true)
    String color;

    @Override
    String tag() {
        return "wall";
    }
}
