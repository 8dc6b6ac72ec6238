package robosim.env.world.xml;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;

/** A {@code <polygon>} element: its points as {@code "x,y x,y ..."} and a height. */
final class PolygonElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String points;
    @JacksonXmlProperty(isAttribute = true)
    String height;
    @JacksonXmlProperty(isAttribute = true)
    String color;

    @Override
    String tag() {
        return "polygon";
    }
}
