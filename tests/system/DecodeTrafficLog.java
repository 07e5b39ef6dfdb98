// Reads a traffic log with LCM's Java classes (lcm.logging.Log, what lcm-spy and
// lcm-logplayer-gui use) and decodes every FSI_ event with the Java types of
// build/java/fsi_lcmtypes.jar: proof that lcm-spy can show our messages. Prints
// "<channel> <count>" per channel and exits 1 when an event does not decode.
import java.io.IOException;
import java.util.TreeMap;

public class DecodeTrafficLog {
    public static void main(String[] args) throws IOException {
        lcm.logging.Log log = new lcm.logging.Log(args[0], "r");
        TreeMap<String, Integer> counts = new TreeMap<>();
        int failures = 0;
        while (true) {
            lcm.logging.Log.Event e;
            try {
                e = log.readNext();
            } catch (java.io.EOFException end) {
                break;
            }
            if (!e.channel.startsWith("FSI_"))
                continue;
            String type = "fsi." + e.channel.substring(4).toLowerCase() + "_t";
            try {
                Class.forName(type).getConstructor(byte[].class).newInstance((Object) e.data);
                counts.merge(e.channel, 1, Integer::sum);
            } catch (ReflectiveOperationException ex) {
                System.err.println(e.channel + ": " + ex.getCause());
                failures++;
            }
        }
        counts.forEach((channel, n) -> System.out.println(channel + " " + n));
        System.exit(failures == 0 ? 0 : 1);
    }
}
