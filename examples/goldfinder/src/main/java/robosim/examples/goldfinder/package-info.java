/**
 * GoldFinder: a team of Pioneers searches a maze for gold by their sensors alone, telling each
 * other what they explored; and the maze generator that makes its worlds.
 */
package robosim.examples.goldfinder;
