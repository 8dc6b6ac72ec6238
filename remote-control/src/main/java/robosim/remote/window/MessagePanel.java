package robosim.remote.window;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JPanel;
import javax.swing.JTextField;
import robosim.remote.MessageDraft;
import robosim.remote.RemoteControl;

/** The send box: to all, to a robot or to a group, and the text; Enter in the text sends too. */
final class MessagePanel extends JPanel {
    private static final long serialVersionUID = 1L;

    MessagePanel(RemoteControl control, DrivePanel.Status status) {
        super(new BorderLayout(4, 4));
        setBorder(BorderFactory.createTitledBorder("send a message"));
        JComboBox<MessageDraft.To> to = new JComboBox<>(MessageDraft.To.values());
        to.setName("to");
        JTextField name = new JTextField(8);
        name.setName("recipient");
        name.setToolTipText("the robot or group (not for ALL)");
        JTextField text = new JTextField(20);
        text.setName("message");
        JButton send = new JButton("Send");
        send.setName("send");
        Runnable sendIt = () -> {
            try {
                status.sent(control.send((MessageDraft.To) to.getSelectedItem(), name.getText(), text.getText()));
                text.setText("");
            } catch (IllegalArgumentException e) {
                status.error(e.getMessage());
            }
        };
        send.addActionListener(e -> sendIt.run());
        text.addActionListener(e -> sendIt.run());
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        top.add(to);
        top.add(name);
        add(top, BorderLayout.NORTH);
        add(text, BorderLayout.CENTER);
        add(send, BorderLayout.EAST);
    }
}
