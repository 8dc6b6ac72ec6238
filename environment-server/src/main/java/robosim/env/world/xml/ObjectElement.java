package robosim.env.world.xml;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;

/** An {@code <object>} element: a movable object (a puck), its position, radius and colour. */
final class ObjectElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String type;
    @JacksonXmlProperty(isAttribute = true)
    String x;
    @JacksonXmlProperty(isAttribute = true)
    String y;
    @JacksonXmlProperty(isAttribute = true)
    String radius;
    @JacksonXmlProperty(isAttribute = true)
    String color;

    @Override
    String tag() {
        return "object";
    }
}
