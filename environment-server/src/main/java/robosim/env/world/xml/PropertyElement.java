package robosim.env.world.xml;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;

/** A {@code <property>} element: one thing robot programs learn of the world in their welcome. */
final class PropertyElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String name;
    @JacksonXmlProperty(isAttribute = true)
    String value;

    @Override
    String tag() {
        return "property";
    }
}
