package robosim.env.world.xml;

/** A {@code <gold>} element: the gold GoldFinder's robots look for, which glows with heat. */
final class GoldElement extends HeatElement {
    @Override
    String tag() {
        return "gold";
    }
}
