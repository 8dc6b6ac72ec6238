package robosim.env.world.xml;

import com.fasterxml.jackson.annotation.JsonSetter;
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;
import java.util.ArrayList;
import java.util.List;

/**
 * The {@code <world>} root element. Children are collected through one adder per element name
 * rather than as unwrapped lists: Jackson replaces an unwrapped list each time its element
 * reappears after another one, so interleaved walls, polygons and heat sources would be lost.
 */
final class WorldElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String name;
    @JacksonXmlProperty(isAttribute = true)
    String width;
    @JacksonXmlProperty(isAttribute = true)
    String height;
    @JacksonXmlProperty(isAttribute = true)
    String stepMs;
    @JacksonXmlProperty(isAttribute = true)
    String boundary;
    @JacksonXmlProperty(isAttribute = true)
    String open;
    @JacksonXmlProperty(isAttribute = true)
    String motors;

    /** The child elements in file order. */
    final List<Element> children = new ArrayList<>();

    @JsonSetter("wall")
    void addWall(WallElement wall) {
        children.add(wall);
    }

    @JsonSetter("polygon")
    void addPolygon(PolygonElement polygon) {
        children.add(polygon);
    }

    @JsonSetter("robot")
    void addRobot(RobotElement robot) {
        children.add(robot);
    }

    @JsonSetter("heat")
    void addHeat(HeatElement heat) {
        children.add(heat);
    }

    @JsonSetter("gold")
    void addGold(GoldElement gold) {
        children.add(gold);
    }

    @JsonSetter("noise")
    void addNoise(NoiseElement noise) {
        children.add(noise);
    }

    @JsonSetter("map")
    void addMap(MapElement map) {
        children.add(map);
    }

    @JsonSetter("comms")
    void addComms(CommsElement comms) {
        children.add(comms);
    }

    @JsonSetter("end")
    void addEnd(EndElement end) {
        children.add(end);
    }

    @JsonSetter("spawn")
    void addSpawn(SpawnElement spawn) {
        children.add(spawn);
    }

    @JsonSetter("object")
    void addObject(ObjectElement object) {
        children.add(object);
    }

    @JsonSetter("property")
    void addProperty(PropertyElement property) {
        children.add(property);
    }

    @Override
    String tag() {
        return "world";
    }
}
