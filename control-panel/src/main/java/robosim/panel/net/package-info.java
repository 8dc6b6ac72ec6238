/** The ControlPanel's side of the control channel: a control client's connection to an Environment's viewer port. */
package robosim.panel.net;
