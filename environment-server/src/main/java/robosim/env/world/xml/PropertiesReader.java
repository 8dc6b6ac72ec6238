package robosim.env.world.xml;

import java.util.LinkedHashMap;
import java.util.Map;
import robosim.protocol.Welcome;

/**
 * Reads a world's {@code <property>} elements into its properties, in file order, with the rules the
 * welcome that carries them to robot programs holds them to (see {@link Welcome}): a name following
 * {@link Welcome#PROPERTY_NAME_RULE} and given once, a value of at most
 * {@value Welcome#MAX_PROPERTY_VALUE} characters, at most {@value Welcome#MAX_PROPERTIES} properties.
 */
final class PropertiesReader {
    private PropertiesReader() {
    }

    /**
     * @param attributes the file's attribute reader
     * @param root       the world element
     * @return the properties, name to value, in file order
     * @throws WorldFileException naming the line of the first property that breaks a rule
     */
    static Map<String, String> read(Attributes attributes, WorldElement root) {
        Map<String, String> properties = new LinkedHashMap<>();
        Map<String, Integer> lines = new LinkedHashMap<>();
        for (Element child : root.children) {
            if (child instanceof PropertyElement p) {
                String name = attributes.text(p, "name", p.name);
                if (!Welcome.PROPERTY_NAME.matcher(name).matches()) {
                    throw attributes.error(p, "attribute name on <property> is " + Attributes.quote(name) + " but "
                            + Welcome.PROPERTY_NAME_RULE);
                }
                if (p.value == null) {
                    throw attributes.error(p, "missing required attribute value on <property> " + name);
                }
                if (p.value.length() > Welcome.MAX_PROPERTY_VALUE) {
                    throw attributes.error(p, "attribute value on <property> " + name + " is " + p.value.length()
                            + " characters but must be at most " + Welcome.MAX_PROPERTY_VALUE);
                }
                Integer first = lines.putIfAbsent(name, p.line());
                if (first != null) {
                    throw attributes.error(p, "property " + name + " is given twice (value "
                            + Attributes.quote(p.value) + "): a world gives each property once; the first is at line "
                            + first);
                }
                if (properties.size() == Welcome.MAX_PROPERTIES) {
                    throw attributes.error(p, "a world has at most " + Welcome.MAX_PROPERTIES
                            + " <property> elements; this is one more");
                }
                properties.put(name, p.value);
            }
        }
        return properties;
    }
}
