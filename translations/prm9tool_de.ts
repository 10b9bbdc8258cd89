<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
    <context>
        <name>Access</name>
        <message>
            <source>{0} is a read-only value of the valve.</source>
            <translation>{0} ist ein nur lesbarer Wert des Ventils.</translation>
        </message>
        <message>
            <source>{0} can only be changed at Expert access level.</source>
            <translation>{0} kann nur in der Expertenstufe geändert werden.</translation>
        </message>
    </context>
    <context>
        <name>App</name>
        <message>
            <source>--device {0}: no such valve</source>
            <translation>--device {0}: Ventil nicht gefunden</translation>
        </message>
        <message>
            <source>{0}

Until the file is corrected, prm9tool knows only the spools it ships.</source>
            <translation>{0}

Bis die Datei korrigiert ist, kennt prm9tool nur die mitgelieferten Schieber.</translation>
        </message>
        <message>
            <source>Spool catalogue</source>
            <translation>Schieberkatalog</translation>
        </message>
        <message>
            <source>--emulator {0}: the serial number must be 1 … 4294967295</source>
            <translation>--emulator {0}: Die Seriennummer muss 1 … 4294967295 sein</translation>
        </message>
        <message>
            <source>Internal error</source>
            <translation>Interner Fehler</translation>
        </message>
        <message>
            <source>prm9tool failed: {0}

The last action may not have been completed. Save your work under a new name and please report this error with the details below.</source>
            <translation>prm9tool ist auf einen Fehler gestoßen: {0}

Die letzte Aktion wurde womöglich nicht vollständig ausgeführt. Speichern Sie Ihre Arbeit unter einem neuen Namen und melden Sie diesen Fehler bitte mit den Details unten.</translation>
        </message>
    </context>
    <context>
        <name>Autotune</name>
        <message>
            <source>The valve did not respond to the step at the present gains: the model is fitted to no response.</source>
            <translation>Das Ventil hat auf den Sprung mit den aktuellen Verstärkungen nicht reagiert: Das Modell ist an keine Antwort angepasst.</translation>
        </message>
        <message>
            <source>The model fits the measurement badly (fit error {0} %, at most {1} %).</source>
            <translation>Das Modell passt schlecht zur Messung (Anpassungsfehler {0} %, höchstens {1} %).</translation>
        </message>
        <message>
            <source>The proposal passes the acceptance profile “{0}” (its steps both ways and the static test).</source>
            <translation>Der Vorschlag besteht das Abnahmeprofil „{0}“ (seine Sprünge in beide Richtungen und die statische Prüfung).</translation>
        </message>
        <message>
            <source>The proposal fails the acceptance profile “{0}”: {1}. Do not accept it unchecked.</source>
            <translation>Der Vorschlag besteht das Abnahmeprofil „{0}“ nicht: {1}. Nicht ungeprüft übernehmen.</translation>
        </message>
    </context>
    <context>
        <name>AutotunePage</name>
        <message>
            <source>Model: gain %1, lags %2 ms, dead time %3 ms (fit error %4 %).</source>
            <translation>Modell: Verstärkung %1, Verzögerungen %2 ms, Totzeit %3 ms (Anpassungsfehler %4 %).</translation>
        </message>
        <message>
            <source>Critical gain Kkr = %1, period Tkr = %2 ms: K = 0.5·Kkr, Ti = 0.8·Tkr, Td = 0.12·Tkr.</source>
            <translation>Kritische Verstärkung Kkr = %1, Periode Tkr = %2 ms: K = 0.5·Kkr, Ti = 0.8·Tkr, Td = 0.12·Tkr.</translation>
        </message>
        <message>
            <source>Do not accept these gains: the identification is not trustworthy.</source>
            <translation>Übernehmen Sie diese Verstärkungen nicht: Die Identifikation ist nicht vertrauenswürdig.</translation>
        </message>
        <message>
            <source>before (measured)</source>
            <translation>vorher (gemessen)</translation>
        </message>
        <message>
            <source>proposed (measured)</source>
            <translation>Vorschlag (gemessen)</translation>
        </message>
        <message>
            <source>proposed (simulated)</source>
            <translation>Vorschlag (simuliert)</translation>
        </message>
        <message>
            <source>time [ms]</source>
            <translation>Zeit [ms]</translation>
        </message>
        <message>
            <source>before</source>
            <translation>vorher</translation>
        </message>
        <message>
            <source>proposed</source>
            <translation>Vorschlag</translation>
        </message>
        <message>
            <source>no response</source>
            <translation>keine Antwort</translation>
        </message>
        <message>
            <source>overshoot %1 %, settling %2</source>
            <translation>Überschwingen %1 %, Ausregelzeit %2</translation>
        </message>
        <message>
            <source>%1 — before: %2; proposed: %3.</source>
            <translation>%1 — vorher: %2; Vorschlag: %3.</translation>
        </message>
        <message>
            <source>steps of %1 % from 0 %, a few times</source>
            <translation>einige Sprünge von 0 % um %1 %</translation>
        </message>
        <message>
            <source>P only with rising gain until the loop oscillates (steps of 5 %, oscillation stopped at ±%1 %)</source>
            <translation>nur P-Anteil mit steigender Verstärkung, bis der Regelkreis schwingt (Sprünge von 5 %, Abbruch bei ±%1 %)</translation>
        </message>
        <message>
            <source>; then the acceptance profile's steps of %1 % and its static test (a triangle of %2 s) with the present and the proposed gains; about %3 s in all</source>
            <translation>; danach die Sprünge des Abnahmeprofils um %1 % und seine statische Prüfung (ein Dreieck von %2 s) mit den aktuellen und den vorgeschlagenen Verstärkungen; insgesamt etwa %3 s</translation>
        </message>
        <message>
            <source>Proposed, simulated on the emulator's firmware (as the controller dialog): %1.</source>
            <translation>Vorschlag, simuliert mit der Firmware des Emulators (wie im Reglerdialog): %1.</translation>
        </message>
        <message>
            <source>Tried before and failed the profile: %1 (%2).</source>
            <translation>Zuvor versucht, Profil nicht bestanden: %1 (%2).</translation>
        </message>
        <message>
            <source>Acceptance steps of %1 %</source>
            <translation>Abnahmesprünge um %1 %</translation>
        </message>
        <message>
            <source>Acceptance steps of %1 % from %2 %</source>
            <translation>Abnahmesprünge um %1 % ab %2 %</translation>
        </message>
        <message>
            <source>Autotune</source>
            <translation>Autotune</translation>
        </message>
        <message>
            <source>Model-based (never oscillates)</source>
            <translation>Modellbasiert (schwingt nie)</translation>
        </message>
        <message>
            <source>Critical gain (APOSYS 10 rule)</source>
            <translation>Kritische Verstärkung (Regel des APOSYS 10)</translation>
        </message>
        <message>
            <source>Method:</source>
            <translation>Verfahren:</translation>
        </message>
        <message>
            <source>Step amplitude:</source>
            <translation>Sprunghöhe:</translation>
        </message>
        <message>
            <source>Target overshoot at most:</source>
            <translation>Überschwingen höchstens:</translation>
        </message>
        <message>
            <source>Target settling time (±2 %) at most:</source>
            <translation>Ausregelzeit (±2 %) höchstens:</translation>
        </message>
        <message>
            <source>Stop when the response leaves 0 ± (band):</source>
            <translation>Abbrechen, wenn die Antwort 0 ± (Band) verlässt:</translation>
        </message>
        <message>
            <source>Run autotune</source>
            <translation>Autotune starten</translation>
        </message>
        <message>
            <source>Accept the proposed gains</source>
            <translation>Vorgeschlagene Verstärkungen übernehmen</translation>
        </message>
        <message>
            <source>Accept anyway (I checked the measurement)</source>
            <translation>Trotzdem übernehmen (ich habe die Messung geprüft)</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>Kennwert</translation>
        </message>
        <message>
            <source>Before</source>
            <translation>Vorher</translation>
        </message>
        <message>
            <source>Proposed</source>
            <translation>Vorschlag</translation>
        </message>
        <message>
            <source>Limit</source>
            <translation>Grenze</translation>
        </message>
        <message>
            <source>Result</source>
            <translation>Ergebnis</translation>
        </message>
    </context>
    <context>
        <name>BlockDialog</name>
        <message>
            <source>Read only: %1 (View → Access level)</source>
            <translation>Nur lesbar: %1 (Ansicht → Berechtigungsstufe)</translation>
        </message>
    </context>
    <context>
        <name>BodePage</name>
        <message>
            <source>a sine sweep %1 … %2 Hz of ±%3 % around %4 %, %5 s</source>
            <translation>ein Sinus-Sweep %1 … %2 Hz von ±%3 % um %4 %, %5 s</translation>
        </message>
        <message>
            <source>above %1 Hz</source>
            <translation>über %1 Hz</translation>
        </message>
        <message>
            <source>not reached</source>
            <translation>nicht erreicht</translation>
        </message>
        <message>
            <source>−3 dB: %1, −90°: %2.</source>
            <translation>−3 dB: %1, −90°: %2.</translation>
        </message>
        <message>
            <source>%1 of %2 samples were lost on the link and left out of the estimate.</source>
            <translation>%1 von %2 Messwerten gingen auf der Verbindung verloren und wurden bei der Schätzung ausgelassen.</translation>
        </message>
        <message>
            <source>The PC held the valve's setpoint for %1 ms at %2 Hz: the sweep counts up to there (at least 4 setpoint changes per period).</source>
            <translation>Der PC hielt den Sollwert des Ventils bei %2 Hz %1 ms lang: der Sweep zählt bis dorthin (mindestens 4 Sollwertänderungen je Periode).</translation>
        </message>
        <message>
            <source>Amplitude:</source>
            <translation>Amplitude:</translation>
        </message>
        <message>
            <source>Operating point:</source>
            <translation>Arbeitspunkt:</translation>
        </message>
        <message>
            <source>From:</source>
            <translation>Von:</translation>
        </message>
        <message>
            <source>To:</source>
            <translation>Bis:</translation>
        </message>
        <message>
            <source>Duration:</source>
            <translation>Dauer:</translation>
        </message>
        <message>
            <source>Measure the frequency response</source>
            <translation>Frequenzgang messen</translation>
        </message>
        <message>
            <source>The link's sample rate limited the sweep to %1 Hz (nothing interpolated).</source>
            <translation>Die Abtastrate der Verbindung begrenzte den Sweep auf %1 Hz (nichts interpoliert).</translation>
        </message>
    </context>
    <context>
        <name>BusLssActions</name>
        <message>
            <source>Find bit rate</source>
            <translation>Bitrate ermitteln</translation>
        </message>
        <message>
            <source>Listen at each bit rate in listen-only mode (nothing is sent)</source>
            <translation>Bei jeder Bitrate im Nur-Hören-Modus mithören (es wird nichts gesendet)</translation>
        </message>
        <message>
            <source>Change node ID by LSS…</source>
            <translation>Node-ID per LSS ändern…</translation>
        </message>
        <message>
            <source>Change bit rate by LSS…</source>
            <translation>Bitrate per LSS ändern…</translation>
        </message>
        <message>
            <source>Listening at each bit rate (listen-only: nothing is sent)…</source>
            <translation>Höre bei jeder Bitrate mit (nur hören: es wird nichts gesendet)…</translation>
        </message>
        <message>
            <source>none identified</source>
            <translation>keiner erkannt</translation>
        </message>
        <message>
            <source>The bus runs at {0} kbit/s (frames from nodes: {1}). Search the bus.</source>
            <translation>Der Bus läuft mit {0} kbit/s (Frames von Knoten: {1}). Durchsuchen Sie den Bus.</translation>
        </message>
        <message>
            <source>Change node ID by LSS</source>
            <translation>Node-ID per LSS ändern</translation>
        </message>
        <message>
            <source>New node ID for serial {0}, now {1} (1…127):</source>
            <translation>Neue Node-ID für Seriennummer {0}, jetzt {1} (1…127):</translation>
        </message>
        <message>
            <source>Node ID {0} is taken: a node answers there. Choose another one.</source>
            <translation>Node-ID {0} ist vergeben: Dort antwortet ein Knoten. Wählen Sie eine andere.</translation>
        </message>
        <message>
            <source>Serial {0} will answer at node {2} instead of {1}, stored in the valve (its node-ID switch must be at 1: LSS). prm9tool's own link moves with it: a connection to can:{1} ends, and prm9tool goes online with can:{2}. A PLC that addresses node {1} no longer reaches the valve. Change it?</source>
            <translation>Seriennummer {0} antwortet dann als Knoten {2} statt {1}, im Ventil gespeichert (sein Node-ID-Schalter muss auf 1 stehen: LSS). Die eigene Verbindung von prm9tool zieht mit um: Eine Verbindung zu can:{1} endet, und prm9tool geht mit can:{2} online. Eine SPS, die Knoten {1} anspricht, erreicht das Ventil nicht mehr. Ändern?</translation>
        </message>
        <message>
            <source>Changing the node ID of serial {0} to {1}…</source>
            <translation>Node-ID von Seriennummer {0} wird auf {1} geändert…</translation>
        </message>
        <message>
            <source>Change bit rate by LSS</source>
            <translation>Bitrate per LSS ändern</translation>
        </message>
        <message>
            <source>New bit rate of the bus:</source>
            <translation>Neue Bitrate des Busses:</translation>
        </message>
        <message>
            <source>Every valve at node-ID switch 1 (LSS) switches from {1} kbit/s to {0} kbit/s together and stores it. Nodes whose switches set the bit rate (node-ID switch 0 or 2…F) and the PLC keep {1} kbit/s: set them too before the machine runs again, or the bus stops working. prm9tool's own link moves to {0} kbit/s. Change the bit rate?</source>
            <translation>Alle Ventile mit Node-ID-Schalter auf 1 (LSS) wechseln gemeinsam von {1} kbit/s auf {0} kbit/s und speichern es. Knoten, deren Schalter die Bitrate bestimmen (Node-ID-Schalter 0 oder 2…F), und die SPS bleiben bei {1} kbit/s: Stellen Sie auch sie um, bevor die Maschine wieder läuft, sonst funktioniert der Bus nicht mehr. Die eigene Verbindung von prm9tool wechselt auf {0} kbit/s. Bitrate ändern?</translation>
        </message>
        <message>
            <source>Changing the bit rate to {0} kbit/s by LSS…</source>
            <translation>Bitrate wird per LSS auf {0} kbit/s geändert…</translation>
        </message>
        <message>
            <source>{0} valve(s) switched to {1} kbit/s. prm9tool cannot change the bit rate of a socketcan interface: sudo ip link set {2} down &amp;&amp; sudo ip link set {2} up type can bitrate {3}, then search the bus.</source>
            <translation>{0} Ventil(e) auf {1} kbit/s umgestellt. prm9tool kann die Bitrate einer socketcan-Schnittstelle nicht ändern: sudo ip link set {2} down &amp;&amp; sudo ip link set {2} up type can bitrate {3}, dann den Bus durchsuchen.</translation>
        </message>
        <message>
            <source>{0} valve(s) switched to {1} kbit/s; prm9tool follows.</source>
            <translation>{0} Ventil(e) auf {1} kbit/s umgestellt; prm9tool folgt.</translation>
        </message>
    </context>
    <context>
        <name>CanBusDialog</name>
        <message>
            <source>CAN bus</source>
            <translation>CAN-Bus</translation>
        </message>
        <message>
            <source>Search the bus</source>
            <translation>Bus durchsuchen</translation>
        </message>
        <message>
            <source>Search the bus to list its nodes.</source>
            <translation>Den Bus durchsuchen, um seine Knoten aufzulisten.</translation>
        </message>
        <message>
            <source>Node</source>
            <translation>Knoten</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Typschlüssel</translation>
        </message>
        <message>
            <source>Serial</source>
            <translation>Seriennummer</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>NMT state</source>
            <translation>NMT-Zustand</translation>
        </message>
        <message>
            <source>Heartbeat</source>
            <translation>Heartbeat</translation>
        </message>
        <message>
            <source>Last EMCY</source>
            <translation>Letzte EMCY</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Beschreibung</translation>
        </message>
        <message>
            <source>Interface (python-can)</source>
            <translation>Schnittstelle (python-can)</translation>
        </message>
        <message>
            <source>Channel</source>
            <translation>Kanal</translation>
        </message>
        <message>
            <source>Bit rate</source>
            <translation>Bitrate</translation>
        </message>
        <message>
            <source>as the adapter is set</source>
            <translation>wie der Adapter eingestellt ist</translation>
        </message>
        <message>
            <source>Online with {0} on this bus: the nodes are shown as they tell about themselves (nothing is sent). Go offline to search the bus or to choose another valve.</source>
            <translation>Online mit {0} an diesem Bus: Die Knoten werden so gezeigt, wie sie sich selbst melden (es wird nichts gesendet). Gehen Sie offline, um den Bus zu durchsuchen oder ein anderes Ventil zu wählen.</translation>
        </message>
        <message>
            <source>Online with {0}: search the bus to watch its nodes; go offline to go online with one of them.</source>
            <translation>Online mit {0}: Durchsuchen Sie den Bus, um seine Knoten zu beobachten; um mit einem von ihnen online zu gehen, gehen Sie zuerst offline.</translation>
        </message>
        <message>
            <source>Searching the bus (node IDs 1…127)…</source>
            <translation>Bus wird durchsucht (Node-IDs 1…127)…</translation>
        </message>
        <message>
            <source>The bus could not be searched: {0}</source>
            <translation>Der Bus konnte nicht durchsucht werden: {0}</translation>
        </message>
        <message numerus="yes">
            <source>%n node(s) answered.</source>
            <translation>
                <numerusform>%n Knoten hat geantwortet.</numerusform>
                <numerusform>%n Knoten haben geantwortet.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n of them PRM9 valve(s).</source>
            <translation>
                <numerusform>Davon %n PRM9-Ventil.</numerusform>
                <numerusform>Davon %n PRM9-Ventile.</numerusform>
            </translation>
        </message>
        <message>
            <source>not identified</source>
            <translation>nicht identifiziert</translation>
        </message>
        <message>
            <source>not a PRM9</source>
            <translation>kein PRM9</translation>
        </message>
        <message>
            <source>{0:.1f} s ago</source>
            <translation>vor {0:.1f} s</translation>
        </message>
        <message>
            <source>none</source>
            <translation>keiner</translation>
        </message>
        <message>
            <source>new on the bus: search again to identify it</source>
            <translation>neu am Bus: erneut suchen, um ihn zu erkennen</translation>
        </message>
        <message>
            <source>the valve prm9tool is online with</source>
            <translation>das Ventil, mit dem prm9tool online ist</translation>
        </message>
        <message>
            <source>heard on the bus</source>
            <translation>am Bus gehört</translation>
        </message>
        <message>
            <source>{0} (boot-up {1:.1f} s ago)</source>
            <translation>{0} (Boot-up vor {1:.1f} s)</translation>
        </message>
        <message>
            <source>silent for {0:.1f} s</source>
            <translation>still seit {0:.1f} s</translation>
        </message>
        <message>
            <source>The bus cannot be watched: {0}</source>
            <translation>Der Bus kann nicht beobachtet werden: {0}</translation>
        </message>
        <message>
            <source>The valve (serial number {0}) does not tell its type key, and its objects do not tell E02 from E04 (-CA). Type key on the valve's label:</source>
            <translation>Das Ventil (Seriennummer {0}) nennt seinen Typenschlüssel nicht, und seine Objekte unterscheiden E02 nicht von E04 (-CA). Typenschlüssel auf dem Typenschild des Ventils:</translation>
        </message>
        <message>
            <source>Type key of the valve</source>
            <translation>Typschlüssel des Ventils</translation>
        </message>
        <message>
            <source>The valve (serial number {0}) does not tell its type key; its objects say {1} -CA. Type key on the valve's label:</source>
            <translation>Das Ventil (Seriennummer {0}) nennt seinen Typschlüssel nicht; seine Objekte sagen {1} -CA. Typschlüssel vom Typenschild des Ventils:</translation>
        </message>
        <message>
            <source>{0} does not fit the valve: its objects say {1} -CA.</source>
            <translation>{0} passt nicht zum Ventil: Seine Objekte sagen {1} -CA.</translation>
        </message>
    </context>
    <context>
        <name>CanLink</name>
        <message>
            <source>CANopen: prm9tool abandoned an SDO transfer: {0} (abort code {1})</source>
            <translation>CANopen: prm9tool hat eine SDO-Übertragung abgebrochen: {0} (Abbruchcode {1})</translation>
        </message>
        <message>
            <source>CANopen: the node did not answer an SDO request in time; asking again</source>
            <translation>CANopen: Der Knoten hat auf eine SDO-Anfrage nicht rechtzeitig geantwortet; die Anfrage wird wiederholt</translation>
        </message>
        <message>
            <source>CANopen: receiving stopped after an error of the CAN interface; go offline and connect again</source>
            <translation>CANopen: Nach einem Fehler der CAN-Schnittstelle werden keine Telegramme mehr empfangen; offline gehen und neu verbinden</translation>
        </message>
        <message>
            <source>CANopen: a received frame could not be processed: {0}</source>
            <translation>CANopen: Ein empfangenes Telegramm konnte nicht verarbeitet werden: {0}</translation>
        </message>
        <message>
            <source>CAN interface ({0}): {1}</source>
            <translation>CAN-Schnittstelle ({0}): {1}</translation>
        </message>
    </context>
    <context>
        <name>CanNodeText</name>
        <message>
            <source>{0} channel {1}</source>
            <translation>{0} Kanal {1}</translation>
        </message>
        <message>
            <source>, {0} bit/s</source>
            <translation>, {0} bit/s</translation>
        </message>
        <message>
            <source>CANopen node {0} on {1}: {2}</source>
            <translation>CANopen-Knoten {0} an {1}: {2}</translation>
        </message>
        <message>
            <source>Node {0} does not answer as a CANopen node: {1}</source>
            <translation>Knoten {0} antwortet nicht als CANopen-Knoten: {1}</translation>
        </message>
        <message>
            <source>Node {0} could not be identified: {1}</source>
            <translation>Knoten {0} konnte nicht identifiziert werden: {1}</translation>
        </message>
        <message>
            <source>none</source>
            <translation>keiner</translation>
        </message>
        <message>
            <source>Node {0}: not a PRM9 (device type 0x{1:X}, vendor {2})</source>
            <translation>Knoten {0}: kein PRM9 (Gerätetyp 0x{1:X}, Hersteller {2})</translation>
        </message>
    </context>
    <context>
        <name>CanopenWindow</name>
        <message>
            <source>CANopen</source>
            <translation>CANopen</translation>
        </message>
        <message>
            <source>The valve reads its two rotary switches at power-up only; the marked rows are the positions it read at its last start. Terminator, node ID and bit rate set here are stored in the valve and take effect after the next restart.</source>
            <translation>Das Ventil liest seine beiden Drehschalter nur beim Einschalten; die markierten Zeilen sind die beim letzten Start gelesenen Stellungen. Hier eingestellter Abschlusswiderstand, Node-ID und Bitrate werden im Ventil gespeichert und nach dem nächsten Neustart wirksam.</translation>
        </message>
        <message>
            <source>Interface / bit-rate switch</source>
            <translation>Schalter Schnittstelle / Bitrate</translation>
        </message>
        <message>
            <source>Node-ID switch</source>
            <translation>Schalter Node-ID</translation>
        </message>
        <message>
            <source>Settings made by software (USB)</source>
            <translation>Einstellungen per Software (USB)</translation>
        </message>
        <message>
            <source>Position</source>
            <translation>Stellung</translation>
        </message>
        <message>
            <source>Interface / bit rate</source>
            <translation>Schnittstelle / Bitrate</translation>
        </message>
        <message>
            <source>Terminator</source>
            <translation>Abschlusswiderstand</translation>
        </message>
        <message>
            <source>Node ID</source>
            <translation>Node-ID</translation>
        </message>
        <message>
            <source>CAN terminator 120 Ω</source>
            <translation>CAN-Abschlusswiderstand 120 Ω</translation>
        </message>
        <message>
            <source>Node ID (node switch at 0)</source>
            <translation>Node-ID (Node-Schalter auf 0)</translation>
        </message>
        <message>
            <source>Bit rate (node switch at 0)</source>
            <translation>Bitrate (Node-Schalter auf 0)</translation>
        </message>
        <message>
            <source>on</source>
            <translation>ein</translation>
        </message>
        <message>
            <source>Overridden: with the node-ID switch at 1 the interface switch has no function; the terminator follows the software setting below.</source>
            <translation>Außer Kraft: Steht der Node-ID-Schalter auf 1, hat der Schnittstellenschalter keine Funktion; der Abschlusswiderstand folgt der Software-Einstellung unten.</translation>
        </message>
        <message>
            <source>Overridden: with the node-ID switch at 1 (LSS) the valve detects the bit rate of the bus.</source>
            <translation>Außer Kraft: Steht der Node-ID-Schalter auf 1 (LSS), erkennt das Ventil die Bitrate des Busses.</translation>
        </message>
        <message>
            <source>Overridden: with the node-ID switch at 0 the bit rate set by software below applies.</source>
            <translation>Außer Kraft: Steht der Node-ID-Schalter auf 0, gilt die unten per Software eingestellte Bitrate.</translation>
        </message>
        <message>
            <source>CANopen off, analog setpoint only</source>
            <translation>CANopen aus, nur analoger Sollwert</translation>
        </message>
        <message>
            <source>reserved (as position 0)</source>
            <translation>reserviert (wie Stellung 0)</translation>
        </message>
        <message>
            <source>off (on by software)</source>
            <translation>aus (per Software ein)</translation>
        </message>
        <message>
            <source>CANopen, %1</source>
            <translation>CANopen, %1</translation>
        </message>
        <message>
            <source>set by software: 1 … 127 (below)</source>
            <translation>per Software: 1 … 127 (unten)</translation>
        </message>
        <message>
            <source>LSS, automatic bit rate</source>
            <translation>LSS, automatische Bitrate</translation>
        </message>
        <message>
            <source>Position read by the valve at its last power-up</source>
            <translation>Beim letzten Einschalten vom Ventil gelesene Stellung</translation>
        </message>
        <message>
            <source>Settings made by software (over CANopen)</source>
            <translation>Einstellungen per Software (über CANopen)</translation>
        </message>
        <message>
            <source>Settings made by software</source>
            <translation>Einstellungen per Software</translation>
        </message>
        <message>
            <source>The node-ID switch is not at 0: the switch sets the node ID.</source>
            <translation>Der Node-ID-Schalter steht nicht auf 0: Der Schalter legt die Node-ID fest.</translation>
        </message>
        <message>
            <source>This valve type has no CANopen interface (no -CA in the type key).</source>
            <translation>Dieser Ventiltyp hat keine CANopen-Schnittstelle (kein -CA im Typschlüssel).</translation>
        </message>
        <message>
            <source>Offline: the switch positions are unknown. Settings changed here go into the document; upload it to the valve and restart the valve.</source>
            <translation>Offline: Die Schalterstellungen sind unbekannt. Hier geänderte Einstellungen gehen in das Dokument; laden Sie es in das Ventil und starten Sie das Ventil neu.</translation>
        </message>
        <message>
            <source>Reading the switch positions from the valve …</source>
            <translation>Schalterstellungen werden aus dem Ventil gelesen …</translation>
        </message>
        <message>
            <source>Switch positions read from the valve at its last power-up.</source>
            <translation>Beim letzten Einschalten aus dem Ventil gelesene Schalterstellungen.</translation>
        </message>
        <message>
            <source>automatic bit rate</source>
            <translation>automatische Bitrate</translation>
        </message>
        <message>
            <source>The node-ID switch is at 0: node ID and bit rate are the ones set below (the interface switch's bit rate is struck through); its positions 9…F still switch the terminator on.</source>
            <translation>Der Node-ID-Schalter steht auf 0: Node-ID und Bitrate sind die unten eingestellten (die Bitrate des Schnittstellenschalters ist durchgestrichen); seine Stellungen 9…F schalten den Abschlusswiderstand trotzdem ein.</translation>
        </message>
        <message>
            <source>The node-ID switch is at 1 (LSS, automatic bit rate): the interface switch has no function, the terminator follows the setting below.</source>
            <translation>Der Node-ID-Schalter steht auf 1 (LSS, automatische Bitrate): Der Schnittstellenschalter hat keine Funktion, der Abschlusswiderstand folgt der Einstellung unten.</translation>
        </message>
        <message>
            <source>After the next restart the valve uses:</source>
            <translation>Nach dem nächsten Neustart verwendet das Ventil:</translation>
        </message>
        <message>
            <source>The valve uses:</source>
            <translation>Das Ventil verwendet:</translation>
        </message>
        <message>
            <source>CANopen off (analog setpoint only).</source>
            <translation>CANopen aus (nur analoger Sollwert).</translation>
        </message>
        <message>
            <source>off</source>
            <translation>aus</translation>
        </message>
        <message>
            <source>node ID %1, %2, terminator %3.</source>
            <translation>Node-ID %1, %2, Abschlusswiderstand %3.</translation>
        </message>
        <message>
            <source>Changed in the document; the valve does not follow the document now. Upload it to the valve; the change takes effect after the valve restarts.</source>
            <translation>Im Dokument geändert; das Ventil folgt dem Dokument gerade nicht. Laden Sie es in das Ventil; die Änderung wird nach einem Neustart des Ventils wirksam.</translation>
        </message>
        <message>
            <source>Changed in the document. Upload it to the valve; the change takes effect after the valve restarts.</source>
            <translation>Im Dokument geändert. Laden Sie es in das Ventil; die Änderung wird nach einem Neustart des Ventils wirksam.</translation>
        </message>
        <message>
            <source>Written to the valve and stored. The change takes effect after the valve restarts (Valve → Restart valve).</source>
            <translation>In das Ventil geschrieben und gespeichert. Die Änderung wird nach einem Neustart des Ventils wirksam (Ventil → Ventil neu starten).</translation>
        </message>
    </context>
    <context>
        <name>ChangePasswordDialog</name>
        <message>
            <source>Change Expert password</source>
            <translation>Expertenpasswort ändern</translation>
        </message>
        <message>
            <source>Current password:</source>
            <translation>Aktuelles Passwort:</translation>
        </message>
        <message>
            <source>New password:</source>
            <translation>Neues Passwort:</translation>
        </message>
        <message>
            <source>Repeat new password:</source>
            <translation>Neues Passwort wiederholen:</translation>
        </message>
        <message>
            <source>The current password is wrong.</source>
            <translation>Das aktuelle Passwort ist falsch.</translation>
        </message>
        <message>
            <source>The new password must have at least {0} characters.</source>
            <translation>Das neue Passwort muss mindestens {0} Zeichen haben.</translation>
        </message>
        <message>
            <source>The two new passwords differ.</source>
            <translation>Die beiden neuen Passwörter stimmen nicht überein.</translation>
        </message>
    </context>
    <context>
        <name>ChannelPanel</name>
        <message>
            <source>Measuring points</source>
            <translation>Messpunkte</translation>
        </message>
        <message>
            <source>At most three measuring points: {0} replaces {1}.</source>
            <translation>Höchstens drei Messpunkte: {0} ersetzt {1}.</translation>
        </message>
        <message>
            <source>At most three measuring points can be recorded at once. Switch one off before adding {0}.</source>
            <translation>Höchstens drei Messpunkte können gleichzeitig aufgezeichnet werden. Schalten Sie einen ab, bevor Sie {0} hinzufügen.</translation>
        </message>
        <message>
            <source>Autoscaled channels with the same unit share one scale and one axis</source>
            <translation>Automatisch skalierte Kanäle mit gleicher Einheit teilen eine Skala und eine Achse</translation>
        </message>
        <message>
            <source>Same scale per unit</source>
            <translation>Gleiche Skala je Einheit</translation>
        </message>
    </context>
    <context>
        <name>Characterize</name>
        <message>
            <source>the model-based autotune needs the controller's output, which this link does not sample (CANopen); use the critical-gain method</source>
            <translation>das modellbasierte Autotuning braucht den Reglerausgang, den diese Verbindung nicht abtastet (CANopen); verwenden Sie die Methode der kritischen Verstärkung</translation>
        </message>
        <message>
            <source>no gains found for the target: {0}</source>
            <translation>keine Verstärkungen für das Ziel gefunden: {0}</translation>
        </message>
        <message>
            <source>stopped by the user; the valve was put back as it was</source>
            <translation>vom Benutzer abgebrochen; das Ventil wurde in den vorherigen Zustand zurückversetzt</translation>
        </message>
        <message>
            <source>the valve reported error {0}: {1}</source>
            <translation>das Ventil meldete den Fehler {0}: {1}</translation>
        </message>
        <message>
            <source>the valve reports error {0} ({1}); nothing was tested</source>
            <translation>das Ventil meldet den Fehler {0} ({1}); es wurde nichts getestet</translation>
        </message>
        <message>
            <source>the valve does not follow its setpoint: device state {0} (a -CA valve with CANopen on waits for its master to enable it); nothing was tested</source>
            <translation>das Ventil folgt seinem Sollwert nicht: Gerätezustand {0} (ein -CA-Ventil mit eingeschaltetem CANopen wartet darauf, dass sein Master es freigibt); es wurde nichts getestet</translation>
        </message>
        <message>
            <source>the valve does not follow its setpoint: device state {0}; nothing was tested</source>
            <translation>das Ventil folgt seinem Sollwert nicht: Gerätezustand {0}; es wurde nichts getestet</translation>
        </message>
        <message>
            <source>the valve did not finish booting</source>
            <translation>das Ventil hat den Start nicht abgeschlossen</translation>
        </message>
        <message>
            <source>flow characteristic not measured: this valve has no object for {0} over this link (measure it over USB)</source>
            <translation>Durchflusskennlinie nicht gemessen: Dieses Ventil hat über diese Verbindung kein Objekt für {0} (über USB messen)</translation>
        </message>
        <message>
            <source>the flow characteristic is measured on E04 valves (with an actuator)</source>
            <translation>die Durchflusskennlinie wird an E04-Ventilen (mit Stellglied) gemessen</translation>
        </message>
        <message>
            <source>this valve has no object for the process controller's gains on this link: the flow characteristic (made proportional for the test) cannot be measured here; nothing was changed — measure it over USB</source>
            <translation>dieses Ventil hat auf dieser Verbindung kein Objekt für die Verstärkungen des Prozessreglers: die Durchflusskennlinie (für den Test proportional gemacht) kann hier nicht gemessen werden; nichts wurde geändert — messen Sie sie über USB</translation>
        </message>
        <message>
            <source>the flow characteristic is measured in control mode 4 (process loop); the valve is in control mode {0}</source>
            <translation>die Durchflusskennlinie wird in Regelmodus 4 (Prozessregelkreis) gemessen; das Ventil ist in Regelmodus {0}</translation>
        </message>
        <message>
            <source>the process controller's Kp is 0: the spool would not move</source>
            <translation>Kp des Prozessreglers ist 0: Der Schieber würde sich nicht bewegen</translation>
        </message>
        <message>
            <source>this valve has no object for {0} on this link (their addresses are this project's, not the manual's): the tuning cannot change them here; nothing was changed — tune these over USB</source>
            <translation>dieses Ventil hat auf dieser Verbindung kein Objekt für {0} (ihre Adressen sind die dieses Projekts, nicht die des Handbuchs): die Abstimmung kann sie hier nicht ändern; nichts wurde geändert — stimmen Sie diese über USB ab</translation>
        </message>
        <message>
            <source>the valve is in control mode {0} (spool position): it has no process loop to test; the process loop runs in control mode 4 (CTRLMODE). Nothing was changed</source>
            <translation>das Ventil ist in Regelmodus {0} (Schieberlage): es hat keinen Prozessregelkreis zum Testen; der Prozessregelkreis arbeitet in Regelmodus 4 (CTRLMODE). Nichts wurde geändert</translation>
        </message>
        <message>
            <source>the valve is in control mode {0} (process loop): its setpoint drives the process controller, not the spool, so the position loop cannot be tested on its own. Choose the process loop, or set CTRLMODE to 2 (spool position) while the valve is not enabled. Nothing was changed</source>
            <translation>das Ventil ist in Regelmodus {0} (Prozessregelkreis): sein Sollwert steuert den Prozessregler, nicht den Schieber, daher lässt sich der Lageregelkreis nicht allein testen. Wählen Sie den Prozessregelkreis oder stellen Sie CTRLMODE auf 2 (Schieberlage), solange das Ventil nicht freigegeben ist. Nichts wurde geändert</translation>
        </message>
        <message>
            <source>{0} left the allowed band {1} ± {2} %; the test was stopped and the valve put back as it was</source>
            <translation>{0} hat das zulässige Band {1} ± {2} % verlassen; der Test wurde abgebrochen und das Ventil wiederhergestellt, wie es war</translation>
        </message>
        <message>
            <source>sweep limited to {0} Hz (of {1} Hz asked) by the link's sample rate of {2} Hz</source>
            <translation>Sweep auf {0} Hz begrenzt (statt {1} Hz) durch die Abtastrate der Verbindung von {2} Hz</translation>
        </message>
        <message>
            <source>sweep usable up to {0} Hz: the PC held the valve's setpoint for {1} ms there (at least {2} updates per period are needed; the PC was busy)</source>
            <translation>Sweep bis {0} Hz verwendbar: der PC hielt den Sollwert des Ventils dort {1} ms lang (mindestens {2} Aktualisierungen je Periode nötig; der PC war ausgelastet)</translation>
        </message>
        <message>
            <source>frequency response: {0} of {1} samples lost on the link, left out of the estimate</source>
            <translation>Frequenzgang: {0} von {1} Abtastwerten auf der Verbindung verloren, in der Schätzung ausgelassen</translation>
        </message>
        <message>
            <source>the history holds no end-of-line test of serial {0} ({1}) to compare with: make its birth certificate first — run the end-of-line test on this valve (Tuning window → Test report → Run the end-of-line test, online; or prm9tool --characterize --device ID --report OUT.pdf) with the history on; nothing was moved</source>
            <translation>der Verlauf enthält keine Endprüfung der Seriennummer {0} ({1}) zum Vergleich: Erstellen Sie zuerst ihre Geburtsurkunde — führen Sie an diesem Ventil die Endprüfung durch (Fenster Einstellung und Charakterisierung → Prüfbericht → Endprüfung starten, online; oder prm9tool --characterize --device ID --report OUT.pdf) bei eingeschaltetem Verlauf; es wurde nichts bewegt</translation>
        </message>
        <message>
            <source>the birth certificate is kept in the history, which is off for this valve: open it with the history on; nothing was moved</source>
            <translation>die Geburtsurkunde steht im Verlauf, der für dieses Ventil ausgeschaltet ist: Öffnen Sie es mit eingeschaltetem Verlauf; es wurde nichts bewegt</translation>
        </message>
    </context>
    <context>
        <name>CommissioningPanel</name>
        <message>
            <source>Commissioning</source>
            <translation>Inbetriebnahme</translation>
        </message>
        <message>
            <source>Enable</source>
            <translation>Freigeben</translation>
        </message>
        <message>
            <source>Control word 0x6040: 08h → 09h → 0Bh → 0Fh (manual §7.6): resets a fault, then DISABLED, HOLD, DEVICE_MODE_ACTIVE. The valve follows its setpoint.</source>
            <translation>Steuerwort 0x6040: 08h → 09h → 0Bh → 0Fh (Handbuch §7.6): setzt einen Fehler zurück, dann DISABLED, HOLD, DEVICE_MODE_ACTIVE. Das Ventil folgt seinem Sollwert.</translation>
        </message>
        <message>
            <source>Disable</source>
            <translation>Sperren</translation>
        </message>
        <message>
            <source>Control word 0x6040: 0Fh → 0Bh → 09h → 08h, back to INIT.</source>
            <translation>Steuerwort 0x6040: 0Fh → 0Bh → 09h → 08h, zurück nach INIT.</translation>
        </message>
        <message>
            <source>NMT start</source>
            <translation>NMT Start</translation>
        </message>
        <message>
            <source>NMT start: operational (PDOs run)</source>
            <translation>NMT Start: operational (PDOs laufen)</translation>
        </message>
        <message>
            <source>NMT pre-operational</source>
            <translation>NMT Pre-operational</translation>
        </message>
        <message>
            <source>NMT enter pre-operational</source>
            <translation>NMT: nach Pre-operational</translation>
        </message>
        <message>
            <source>NMT stop</source>
            <translation>NMT Stopp</translation>
        </message>
        <message>
            <source>NMT stop: only NMT is answered</source>
            <translation>NMT Stopp: Nur NMT wird beantwortet</translation>
        </message>
        <message>
            <source>The valve follows its setpoint (DEVICE_MODE_ACTIVE).</source>
            <translation>Das Ventil folgt seinem Sollwert (DEVICE_MODE_ACTIVE).</translation>
        </message>
        <message>
            <source>The valve does not follow its setpoint: {0}</source>
            <translation>Das Ventil folgt seinem Sollwert nicht: {0}</translation>
        </message>
    </context>
    <context>
        <name>Compare</name>
        <message>
            <source>The type keys differ: {0} is {1}, {2} is {3}.</source>
            <translation>Die Typenschlüssel unterscheiden sich: {0} ist {1}, {2} ist {3}.</translation>
        </message>
        <message>
            <source>The valve variants differ: only the parameters both have are compared; {0} parameters that one side lacks are left out.</source>
            <translation>Die Ventilvarianten unterscheiden sich: verglichen werden nur die Parameter, die beide haben; {0} Parameter, die einer Seite fehlen, bleiben außen vor.</translation>
        </message>
        <message>
            <source>not on this valve</source>
            <translation>nicht in diesem Ventil</translation>
        </message>
        <message>
            <source>not on the valve it was read from</source>
            <translation>nicht in dem Ventil, aus dem gelesen wurde</translation>
        </message>
    </context>
    <context>
        <name>CompareDialog</name>
        <message>
            <source>Compare parameters</source>
            <translation>Parameter vergleichen</translation>
        </message>
        <message>
            <source>Differences only</source>
            <translation>Nur Unterschiede</translation>
        </message>
        <message>
            <source>All blocks</source>
            <translation>Alle Blöcke</translation>
        </message>
        <message>
            <source>Basic level</source>
            <translation>Basisstufe</translation>
        </message>
        <message>
            <source>Expert level</source>
            <translation>Expertenstufe</translation>
        </message>
        <message>
            <source>Block:</source>
            <translation>Block:</translation>
        </message>
        <message>
            <source>Access level:</source>
            <translation>Berechtigungsstufe:</translation>
        </message>
        <message>
            <source>Tick every shown value of {0}</source>
            <translation>Alle angezeigten Werte von „{0}“ ankreuzen</translation>
        </message>
        <message>
            <source>Close</source>
            <translation>Schließen</translation>
        </message>
        <message numerus="yes">
            <source>Write %n ticked value(s) into the valve</source>
            <translation>
                <numerusform>%n angekreuzten Wert in das Ventil schreiben</numerusform>
                <numerusform>%n angekreuzte Werte in das Ventil schreiben</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Take %n ticked value(s) into the document</source>
            <translation>
                <numerusform>%n angekreuzten Wert in das Dokument übernehmen</numerusform>
                <numerusform>%n angekreuzte Werte in das Dokument übernehmen</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Copy %n ticked value(s) into “{0}”</source>
            <translation>
                <numerusform>%n angekreuzten Wert nach „{0}“ kopieren</numerusform>
                <numerusform>%n angekreuzte Werte nach „{0}“ kopieren</numerusform>
            </translation>
        </message>
        <message>
            <source>Every row starts with the valve's value ticked. Tick the document's value where the document is right, then press Apply: the document takes the ticked valve values and the valve the ticked document values.</source>
            <translation>In jeder Zeile ist zunächst der Wert des Ventils angekreuzt. Kreuzen Sie den Wert des Dokuments an, wo das Dokument richtig ist, und drücken Sie dann „Übernehmen“: Das Dokument erhält die angekreuzten Werte des Ventils, das Ventil die angekreuzten Werte des Dokuments.</translation>
        </message>
        <message>
            <source>Tick the values to take, in either column; then take them into the document, or write them into the valve (online with this valve).</source>
            <translation>Kreuzen Sie die gewünschten Werte in einer der beiden Spalten an; übernehmen Sie sie dann in das Dokument oder schreiben Sie sie in das Ventil (online mit diesem Ventil).</translation>
        </message>
        <message>
            <source>Shown for comparison only.</source>
            <translation>Nur zum Vergleich angezeigt.</translation>
        </message>
        <message>
            <source>Apply: each side takes the ticked values</source>
            <translation>Übernehmen: Jede Seite erhält die angekreuzten Werte</translation>
        </message>
        <message>
            <source>Tick values in the column “{0}” first</source>
            <translation>Kreuzen Sie zuerst Werte in der Spalte „{0}“ an</translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) differ</source>
            <translation>
                <numerusform>%n Parameter unterscheidet sich</numerusform>
                <numerusform>%n Parameter unterscheiden sich</numerusform>
            </translation>
        </message>
        <message>
            <source>To write values into the valve: tick them in the column “{0}”, then press the button below.</source>
            <translation>Werte in das Ventil schreiben: in der Spalte „{0}“ ankreuzen, dann die Schaltfläche unten drücken.</translation>
        </message>
        <message>
            <source>To take values into the document: tick them in the column “{0}”, then press the button below.</source>
            <translation>Werte in das Dokument übernehmen: in der Spalte „{0}“ ankreuzen, dann die Schaltfläche unten drücken.</translation>
        </message>
        <message>
            <source>To copy values into “{0}”: tick them in the column “{1}”, then press the button below.</source>
            <translation>Werte nach „{0}“ kopieren: in der Spalte „{1}“ ankreuzen, dann die Schaltfläche unten drücken.</translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) only on one side</source>
            <translation>
                <numerusform>%n Parameter nur auf einer Seite</numerusform>
                <numerusform>%n Parameter nur auf einer Seite</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) not on the valve, not compared</source>
            <translation>
                <numerusform>%n Parameter nicht im Ventil, nicht verglichen</numerusform>
                <numerusform>%n Parameter nicht im Ventil, nicht verglichen</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n shown</source>
            <translation>
                <numerusform>%n angezeigt</numerusform>
                <numerusform>%n angezeigt</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>CompareTableModel</name>
        <message>
            <source>Mnemonic</source>
            <translation>Kürzel</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Beschreibung</translation>
        </message>
        <message>
            <source>One side's valve type has no such parameter; it cannot be chosen.</source>
            <translation>Der Ventiltyp einer Seite hat diesen Parameter nicht; er kann nicht gewählt werden.</translation>
        </message>
        <message>
            <source>The valve type has this parameter, but the valve does not (a valve over CANopen without this object): not compared, not a difference; it cannot be chosen.</source>
            <translation>Der Ventiltyp hat diesen Parameter, das Ventil aber nicht (ein Ventil über CANopen ohne dieses Objekt): nicht verglichen, kein Unterschied; er kann nicht gewählt werden.</translation>
        </message>
    </context>
    <context>
        <name>CompareWorkflow</name>
        <message>
            <source>History: {0}</source>
            <translation>Verlauf: {0}</translation>
        </message>
        <message>
            <source>Document</source>
            <translation>Dokument</translation>
        </message>
        <message>
            <source>Valve {0}</source>
            <translation>Ventil {0}</translation>
        </message>
        <message>
            <source>Factory defaults</source>
            <translation>Werkseinstellungen</translation>
        </message>
        <message>
            <source>Compare with file</source>
            <translation>Mit Datei vergleichen</translation>
        </message>
        <message>
            <source>Parameter files (*.prm);;All files (*)</source>
            <translation>Parameterdateien (*.prm);;Alle Dateien (*)</translation>
        </message>
        <message>
            <source>{0} cannot be compared.</source>
            <translation>{0} kann nicht verglichen werden.</translation>
        </message>
        <message>
            <source>Values taken from {0}</source>
            <translation>Werte aus {0} übernommen</translation>
        </message>
        <message>
            <source>Compare with valve</source>
            <translation>Mit Ventil vergleichen</translation>
        </message>
        <message>
            <source>Go online with the valve first (Communication → Online mode).</source>
            <translation>Zuerst mit dem Ventil online gehen (Kommunikation → Online-Modus).</translation>
        </message>
        <message>
            <source>Values taken from the valve</source>
            <translation>Werte aus dem Ventil übernommen</translation>
        </message>
        <message>
            <source>Values chosen from the valve</source>
            <translation>Aus dem Ventil gewählte Werte</translation>
        </message>
        <message>
            <source>Online: document and valve agree</source>
            <translation>Online: Dokument und Ventil stimmen überein</translation>
        </message>
        <message>
            <source>Parameters restored from the history</source>
            <translation>Parameter aus dem Verlauf wiederhergestellt</translation>
        </message>
        <message numerus="yes">
            <source>%n value(s) taken from the history</source>
            <translation>
                <numerusform>%n Wert aus dem Verlauf übernommen</numerusform>
                <numerusform>%n Werte aus dem Verlauf übernommen</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>ControlPanel</name>
        <message>
            <source>Recording</source>
            <translation>Aufzeichnung</translation>
        </message>
        <message>
            <source>Interval</source>
            <translation>Intervall</translation>
        </message>
        <message>
            <source>Time window</source>
            <translation>Zeitfenster</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>Start</translation>
        </message>
        <message>
            <source>Stop</source>
            <translation>Stopp</translation>
        </message>
        <message>
            <source>Trigger</source>
            <translation>Trigger</translation>
        </message>
        <message>
            <source>Roll (no trigger)</source>
            <translation>Rollen (ohne Trigger)</translation>
        </message>
        <message>
            <source>Auto</source>
            <translation>Auto</translation>
        </message>
        <message>
            <source>Normal</source>
            <translation>Normal</translation>
        </message>
        <message>
            <source>Single</source>
            <translation>Einzeln</translation>
        </message>
        <message>
            <source>Rising edge</source>
            <translation>Steigende Flanke</translation>
        </message>
        <message>
            <source>Falling edge</source>
            <translation>Fallende Flanke</translation>
        </message>
        <message>
            <source>Pre-trigger</source>
            <translation>Vortrigger</translation>
        </message>
        <message>
            <source>Trigger level in the trigger channel's unit</source>
            <translation>Triggerpegel in der Einheit des Triggerkanals</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Fortsetzen</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>Pause</translation>
        </message>
        <message>
            <source>CSV of the visible window…</source>
            <translation>CSV des sichtbaren Fensters…</translation>
        </message>
        <message>
            <source>CSV of the whole recording…</source>
            <translation>CSV der gesamten Aufzeichnung…</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>Export</translation>
        </message>
        <message>
            <source>Level</source>
            <translation>Pegel</translation>
        </message>
        <message>
            <source>PNG image of the plot…</source>
            <translation>PNG-Bild des Diagramms…</translation>
        </message>
        <message>
            <source>Trigger channel</source>
            <translation>Triggerkanal</translation>
        </message>
    </context>
    <context>
        <name>ControllerDialog</name>
        <message>
            <source>Tuning and autotune…</source>
            <translation>Einstellung und Autotune…</translation>
        </message>
        <message>
            <source>No simulation available.</source>
            <translation>Keine Simulation verfügbar.</translation>
        </message>
        <message>
            <source>Simulation failed: %1</source>
            <translation>Simulation fehlgeschlagen: %1</translation>
        </message>
        <message>
            <source>setpoint</source>
            <translation>Sollwert</translation>
        </message>
        <message>
            <source>applied values</source>
            <translation>übernommene Werte</translation>
        </message>
        <message>
            <source>actual value</source>
            <translation>Istwert</translation>
        </message>
        <message>
            <source>Time (ms)</source>
            <translation>Zeit (ms)</translation>
        </message>
        <message>
            <source>Value (%)</source>
            <translation>Wert (%)</translation>
        </message>
        <message>
            <source>Simulated on the emulator's plant (no twin of this serial).</source>
            <translation>Simuliert mit der Strecke des Emulators (kein Zwilling dieser Seriennummer).</translation>
        </message>
        <message>
            <source>Simulated on the twin of serial {0} (fitted {1}).</source>
            <translation>Simuliert mit dem Zwilling der Seriennummer {0} (angepasst {1}).</translation>
        </message>
    </context>
    <context>
        <name>CurrentDitherDialog</name>
        <message>
            <source>Nominal coil current CURNORM: %1 mA — no limit may exceed it.</source>
            <translation>Nennstrom der Spule CURNORM: %1 mA – keine Grenze darf ihn überschreiten.</translation>
        </message>
        <message>
            <source>Dither: ±%1 mA peak (DTAMP 100 % = %2 % of CURNORM).</source>
            <translation>Dither: ±%1 mA Spitze (DTAMP 100 % = %2 % von CURNORM).</translation>
        </message>
        <message>
            <source>coil %1</source>
            <translation>Spule %1</translation>
        </message>
        <message>
            <source>limit %1</source>
            <translation>Grenze %1</translation>
        </message>
        <message>
            <source>Coil current (mA)</source>
            <translation>Spulenstrom (mA)</translation>
        </message>
        <message>
            <source>Coil current (mA), coil B downwards</source>
            <translation>Spulenstrom (mA), Spule B nach unten</translation>
        </message>
        <message>
            <source>Time (ms)</source>
            <translation>Zeit (ms)</translation>
        </message>
    </context>
    <context>
        <name>CursorPanel</name>
        <message>
            <source>Cursors</source>
            <translation>Cursor</translation>
        </message>
        <message>
            <source>Switch the cursors on to measure.</source>
            <translation>Schalten Sie die Cursor zum Messen ein.</translation>
        </message>
        <message>
            <source>Δt = {0}    1/Δt = {1}</source>
            <translation>Δt = {0}    1/Δt = {1}</translation>
        </message>
        <message>
            <source>Cursors A/B</source>
            <translation>Cursor A/B</translation>
        </message>
    </context>
    <context>
        <name>CurveEditor</name>
        <message>
            <source>1:1</source>
            <translation>1:1</translation>
        </message>
        <message>
            <source>characteristic</source>
            <translation>Kennlinie</translation>
        </message>
    </context>
    <context>
        <name>DcfExport</name>
        <message>
            <source>Export DCF</source>
            <translation>DCF exportieren</translation>
        </message>
        <message>
            <source>CANopen device configuration (*.dcf)</source>
            <translation>CANopen-Gerätekonfiguration (*.dcf)</translation>
        </message>
        <message>
            <source>Cannot write “{0}”: {1}</source>
            <translation>„{0}“ kann nicht geschrieben werden: {1}</translation>
        </message>
        <message>
            <source>DCF saved as {0} (node {1})</source>
            <translation>DCF gespeichert als {0} (Knoten {1})</translation>
        </message>
    </context>
    <context>
        <name>DiagramBlock</name>
        <message>
            <source>spool position (LVDT)</source>
            <translation>Schieberlage (LVDT)</translation>
        </message>
        <message>
            <source>Setpoint input</source>
            <translation>Sollwerteingang</translation>
        </message>
        <message>
            <source>Threshold</source>
            <translation>Schwelle</translation>
        </message>
        <message>
            <source>Gain &amp; offset</source>
            <translation>Verstärkung &amp; Offset</translation>
        </message>
        <message>
            <source>Linearization</source>
            <translation>Linearisierung</translation>
        </message>
        <message>
            <source>Ramps</source>
            <translation>Rampen</translation>
        </message>
        <message>
            <source>Deviation gain &amp; offset</source>
            <translation>Abweichung: Verstärkung &amp; Offset</translation>
        </message>
        <message>
            <source>Process PIDT1</source>
            <translation>Prozessregler PIDT1</translation>
        </message>
        <message>
            <source>External sensor</source>
            <translation>Externer Sensor</translation>
        </message>
        <message>
            <source>Sensor offset &amp; gain</source>
            <translation>Sensor: Offset &amp; Verstärkung</translation>
        </message>
        <message>
            <source>Sensor linearization</source>
            <translation>Sensor-Linearisierung</translation>
        </message>
        <message>
            <source>Position PIDT1</source>
            <translation>Lageregler PIDT1</translation>
        </message>
        <message>
            <source>Current limiter</source>
            <translation>Strombegrenzung</translation>
        </message>
        <message>
            <source>Dither</source>
            <translation>Dither</translation>
        </message>
        <message>
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
        <message>
            <source>CANopen</source>
            <translation>CANopen</translation>
        </message>
        <message>
            <source>Supply</source>
            <translation>Versorgung</translation>
        </message>
    </context>
    <context>
        <name>DiagramSummary</name>
        <message>
            <source>Polarity: %1</source>
            <translation>Polarität: %1</translation>
        </message>
        <message>
            <source>Threshold %1</source>
            <translation>Schwelle %1</translation>
        </message>
        <message>
            <source>Gain %1</source>
            <translation>Verstärkung %1</translation>
        </message>
        <message>
            <source>Offset %1</source>
            <translation>Offset %1</translation>
        </message>
        <message>
            <source>9-point curve on</source>
            <translation>9-Punkt-Kennlinie ein</translation>
        </message>
        <message>
            <source>off (1:1)</source>
            <translation>aus (1:1)</translation>
        </message>
        <message>
            <source>Coil %1: %2</source>
            <translation>Spule %1: %2</translation>
        </message>
        <message>
            <source>Amplitude %1</source>
            <translation>Amplitude %1</translation>
        </message>
        <message>
            <source>Frequency %1</source>
            <translation>Frequenz %1</translation>
        </message>
        <message>
            <source>coils A and B</source>
            <translation>Spulen A und B</translation>
        </message>
        <message>
            <source>coil A only</source>
            <translation>nur Spule A</translation>
        </message>
        <message>
            <source>coil B only</source>
            <translation>nur Spule B</translation>
        </message>
        <message>
            <source>Voltage, temperature</source>
            <translation>Spannung, Temperatur</translation>
        </message>
        <message>
            <source>(live values)</source>
            <translation>(Live-Werte)</translation>
        </message>
        <message>
            <source>CANopen off</source>
            <translation>CANopen aus</translation>
        </message>
        <message>
            <source>analog setpoint</source>
            <translation>analoger Sollwert</translation>
        </message>
        <message>
            <source>auto bit rate</source>
            <translation>Bitrate auto</translation>
        </message>
        <message>
            <source>Node ID %1 · %2</source>
            <translation>Node-ID %1 · %2</translation>
        </message>
        <message>
            <source>Rotary switches: interface %1, node ID %2 (read by the valve at power-up; before a valve was read, the delivery state).</source>
            <translation>Drehschalter: Schnittstelle %1, Node-ID %2 (vom Ventil beim Einschalten gelesen; solange kein Ventil gelesen wurde, der Auslieferungszustand).</translation>
        </message>
        <message>
            <source>Terminator %1</source>
            <translation>Busabschluss %1</translation>
        </message>
    </context>
    <context>
        <name>DiagramView</name>
        <message>
            <source>Values measured by the valve; see the red measuring points.</source>
            <translation>Vom Ventil gemessene Werte; siehe die roten Messpunkte.</translation>
        </message>
        <message>
            <source>Click to edit: %1</source>
            <translation>Zum Bearbeiten klicken: %1</translation>
        </message>
        <message>
            <source>(View → Access level)</source>
            <translation>(Ansicht → Berechtigungsstufe)</translation>
        </message>
        <message>
            <source>Online, the valve type is that of the connected valve.</source>
            <translation>Online ist der Ventiltyp der des angeschlossenen Ventils.</translation>
        </message>
        <message>
            <source>%1 — no live value now: the valve streams three measuring points at a time and the oscilloscope is recording others (over CANopen: the valve has no object for this point).</source>
            <translation>%1 – zurzeit kein Messwert: Das Ventil überträgt drei Messpunkte gleichzeitig, und das Oszilloskop zeichnet andere auf (über CANopen: Das Ventil hat für diesen Punkt kein Objekt).</translation>
        </message>
        <message>
            <source>%1 — click to show it in the oscilloscope</source>
            <translation>%1 – klicken, um ihn im Oszilloskop anzuzeigen</translation>
        </message>
        <message>
            <source>%1 — offline: measuring points show live values only with a valve online.</source>
            <translation>%1 – offline: Messpunkte zeigen Live-Werte nur mit einem Ventil online.</translation>
        </message>
        <message>
            <source>Zoom to fit</source>
            <translation>An Fenster anpassen</translation>
        </message>
        <message>
            <source>Zoom in</source>
            <translation>Vergrößern</translation>
        </message>
        <message>
            <source>Zoom out</source>
            <translation>Verkleinern</translation>
        </message>
    </context>
    <context>
        <name>Edits</name>
        <message>
            <source>Valve selection {0}</source>
            <translation>Ventilauswahl {0}</translation>
        </message>
        <message>
            <source>{0}{1} rounded to {2}{1} (resolution {3}{1})</source>
            <translation>{0}{1} auf {2}{1} gerundet (Auflösung {3}{1})</translation>
        </message>
        <message>
            <source>All ramps = {0}{1}</source>
            <translation>Alle Rampen = {0}{1}</translation>
        </message>
    </context>
    <context>
        <name>EdsExport</name>
        <message>
            <source>Export EDS</source>
            <translation>EDS exportieren</translation>
        </message>
        <message>
            <source>CANopen electronic data sheet (*.eds)</source>
            <translation>CANopen-Gerätebeschreibung (*.eds)</translation>
        </message>
        <message>
            <source>Cannot write “{0}”: {1}</source>
            <translation>„{0}“ kann nicht geschrieben werden: {1}</translation>
        </message>
        <message>
            <source>EDS saved as {0}</source>
            <translation>EDS gespeichert als {0}</translation>
        </message>
    </context>
    <context>
        <name>Emcy</name>
        <message>
            <source>Warning: electronics temperature above 70 °C</source>
            <translation>Warnung: Elektroniktemperatur über 70 °C</translation>
        </message>
        <message>
            <source>General error</source>
            <translation>Allgemeiner Fehler</translation>
        </message>
        <message>
            <source>Supply voltage out of range</source>
            <translation>Versorgungsspannung außerhalb des Bereichs</translation>
        </message>
        <message>
            <source>Setpoint signal error (e.g. 4…20 mA wire break)</source>
            <translation>Fehler Sollwertsignal (z. B. Kabelbruch 4…20 mA)</translation>
        </message>
        <message>
            <source>Electronics temperature above 100 °C</source>
            <translation>Elektroniktemperatur über 100 °C</translation>
        </message>
        <message>
            <source>External sensor error</source>
            <translation>Fehler externer Sensor</translation>
        </message>
        <message>
            <source>Solenoid A over-current or disconnected</source>
            <translation>Spule A Überstrom oder nicht angeschlossen</translation>
        </message>
        <message>
            <source>Solenoid B over-current or disconnected</source>
            <translation>Spule B Überstrom oder nicht angeschlossen</translation>
        </message>
        <message>
            <source>Internal position sensor error</source>
            <translation>Fehler interner Wegsensor</translation>
        </message>
        <message>
            <source>Unknown error</source>
            <translation>Unbekannter Fehler</translation>
        </message>
        <message>
            <source>ok</source>
            <translation>ok</translation>
        </message>
        <message>
            <source>CANopen communication error (heartbeat, SYNC or RPDO missing)</source>
            <translation>CANopen-Kommunikationsfehler (Heartbeat, SYNC oder RPDO fehlt)</translation>
        </message>
        <message>
            <source>CANopen RPDO too short: not processed</source>
            <translation>CANopen-RPDO zu kurz: nicht verarbeitet</translation>
        </message>
    </context>
    <context>
        <name>EmulatedValve</name>
        <message>
            <source>Coil A disconnected</source>
            <translation>Spule A abgeklemmt</translation>
        </message>
        <message>
            <source>Coil A short circuit (over-current)</source>
            <translation>Spule A Kurzschluss (Überstrom)</translation>
        </message>
        <message>
            <source>Coil B disconnected</source>
            <translation>Spule B abgeklemmt</translation>
        </message>
        <message>
            <source>Coil B short circuit (over-current)</source>
            <translation>Spule B Kurzschluss (Überstrom)</translation>
        </message>
        <message>
            <source>Setpoint wire break</source>
            <translation>Drahtbruch Sollwert</translation>
        </message>
        <message>
            <source>External sensor wire break</source>
            <translation>Drahtbruch externer Sensor</translation>
        </message>
        <message>
            <source>Spool position sensor (LVDT) wire break</source>
            <translation>Drahtbruch Schieberwegsensor (LVDT)</translation>
        </message>
        <message>
            <source>Supply too low (17 V)</source>
            <translation>Versorgung zu niedrig (17 V)</translation>
        </message>
        <message>
            <source>Supply too high (31 V)</source>
            <translation>Versorgung zu hoch (31 V)</translation>
        </message>
        <message>
            <source>Over-temperature (105 °C)</source>
            <translation>Übertemperatur (105 °C)</translation>
        </message>
    </context>
    <context>
        <name>EmulatedValveDialog</name>
        <message>
            <source>Emulated valve</source>
            <translation>Emuliertes Ventil</translation>
        </message>
        <message>
            <source>Setpoint input [{0}]:</source>
            <translation>Sollwerteingang [{0}]:</translation>
        </message>
        <message>
            <source>External sensor input [{0}]:</source>
            <translation>Eingang externer Sensor [{0}]:</translation>
        </message>
        <message>
            <source>Supply voltage [V]:</source>
            <translation>Versorgungsspannung [V]:</translation>
        </message>
        <message>
            <source>Ambient temperature [°C]:</source>
            <translation>Umgebungstemperatur [°C]:</translation>
        </message>
        <message>
            <source>Interface / bit-rate switch:</source>
            <translation>Schalter Schnittstelle / Bitrate:</translation>
        </message>
        <message>
            <source>Node-ID switch:</source>
            <translation>Schalter Node-ID:</translation>
        </message>
        <message>
            <source>The valve reads its rotary switches at power-up only: restart it (Valve → Restart valve) for a new position to apply. The setpoint input counts only while the valve takes its setpoint from the analog input (no CANopen, no setpoint generator).</source>
            <translation>Das Ventil liest seine Drehschalter nur beim Einschalten: Starten Sie es neu (Ventil → Ventil neu starten), damit eine neue Stellung gilt. Der Sollwerteingang zählt nur, solange das Ventil seinen Sollwert vom Analogeingang nimmt (kein CANopen, kein Sollwertgenerator).</translation>
        </message>
        <message>
            <source>node ID and bit rate by software (NODEID, BITRATE)</source>
            <translation>Node-ID und Bitrate per Software (NODEID, BITRATE)</translation>
        </message>
        <message>
            <source>LSS: node ID from an LSS master, automatic bit rate</source>
            <translation>LSS: Node-ID von einem LSS-Master, automatische Bitrate</translation>
        </message>
        <message>
            <source>node {0}</source>
            <translation>Knoten {0}</translation>
        </message>
    </context>
    <context>
        <name>EmulatedValveMenu</name>
        <message>
            <source>E&amp;mulated valve</source>
            <translation>E&amp;muliertes Ventil</translation>
        </message>
        <message>
            <source>&amp;Inputs and switches…</source>
            <translation>&amp;Eingänge und Schalter…</translation>
        </message>
        <message>
            <source>Setpoint and sensor signals, supply, temperature and rotary switches</source>
            <translation>Sollwert- und Sensorsignal, Versorgung, Temperatur und Drehschalter</translation>
        </message>
        <message>
            <source>&amp;Pull the USB cable</source>
            <translation>USB-Kabel &amp;ziehen</translation>
        </message>
        <message>
            <source>The link drops as when a real cable is pulled; it stays out until plugged back</source>
            <translation>Die Verbindung bricht ab wie bei einem gezogenen Kabel; es bleibt draußen, bis es wieder eingesteckt wird</translation>
        </message>
        <message>
            <source>Plug the USB &amp;cable back in</source>
            <translation>USB-&amp;Kabel wieder einstecken</translation>
        </message>
        <message>
            <source>The emulated valve is connected again; prm9tool finds it by itself</source>
            <translation>Das emulierte Ventil ist wieder angeschlossen; prm9tool findet es von selbst</translation>
        </message>
        <message>
            <source>Inject this fault into the emulated valve, or repair it</source>
            <translation>Diesen Fehler im emulierten Ventil auslösen oder beheben</translation>
        </message>
    </context>
    <context>
        <name>EmulatorDialog</name>
        <message>
            <source>Add emulated valve</source>
            <translation>Emuliertes Ventil hinzufügen</translation>
        </message>
        <message>
            <source>none: the emulator's plant</source>
            <translation>keine: die Strecke des Emulators</translation>
        </message>
        <message>
            <source>A twin brings its own type key, serial number and parameter set.</source>
            <translation>Ein Zwilling bringt seinen eigenen Typenschlüssel, seine Seriennummer und seinen Parametersatz mit.</translation>
        </message>
        <message>
            <source>Browse…</source>
            <translation>Durchsuchen…</translation>
        </message>
        <message>
            <source>Serial number:</source>
            <translation>Seriennummer:</translation>
        </message>
        <message>
            <source>Twin from the history:</source>
            <translation>Zwilling aus dem Verlauf:</translation>
        </message>
        <message>
            <source>Twin file:</source>
            <translation>Zwillingsdatei:</translation>
        </message>
        <message>
            <source>none</source>
            <translation>keiner</translation>
        </message>
        <message>
            <source>fitted {0}: {1}</source>
            <translation>angepasst {0}: {1}</translation>
        </message>
        <message>
            <source>{0} (cannot be used: {1})</source>
            <translation>{0} (nicht verwendbar: {1})</translation>
        </message>
        <message>
            <source>Twin file</source>
            <translation>Zwillingsdatei</translation>
        </message>
        <message>
            <source>Twin files (*.toml)</source>
            <translation>Zwillingsdateien (*.toml)</translation>
        </message>
    </context>
    <context>
        <name>Errors</name>
        <message>
            <source>The valve could not be reached.</source>
            <translation>Das Ventil ist nicht erreichbar.</translation>
        </message>
        <message>
            <source>The valve did not answer in time.</source>
            <translation>Das Ventil hat nicht rechtzeitig geantwortet.</translation>
        </message>
        <message>
            <source>The valve answered something prm9tool does not understand.</source>
            <translation>Das Ventil hat etwas geantwortet, das prm9tool nicht versteht.</translation>
        </message>
        <message>
            <source>The connection to the valve is broken.</source>
            <translation>Die Verbindung zum Ventil ist unterbrochen.</translation>
        </message>
        <message>
            <source>The CAN adapter went bus-off: check the wiring, termination and bit rate.</source>
            <translation>Der CAN-Adapter ist im Zustand Bus-Off: Verkabelung, Abschlusswiderstände und Bitrate prüfen.</translation>
        </message>
        <message>
            <source>The emulated valve could not join the CAN bus; it works over USB without CAN.</source>
            <translation>Das emulierte Ventil konnte dem CAN-Bus nicht beitreten; es arbeitet über USB ohne CAN.</translation>
        </message>
        <message>
            <source>The CAN interface could not be opened.</source>
            <translation>Die CAN-Schnittstelle konnte nicht geöffnet werden.</translation>
        </message>
        <message>
            <source>The valve refused the access.</source>
            <translation>Das Ventil hat den Zugriff abgelehnt.</translation>
        </message>
        <message>
            <source>The history database cannot be used.</source>
            <translation>Die Verlaufsdatenbank kann nicht benutzt werden.</translation>
        </message>
        <message>
            <source>node {0} is NMT {1}: the valve takes RPDOs only when OPERATIONAL — start it first (Valve status → Commissioning: NMT start)</source>
            <translation>Knoten {0} ist NMT {1}: Das Ventil nimmt RPDOs nur im Zustand OPERATIONAL an — starten Sie ihn zuerst (Ventilstatus → Inbetriebnahme: NMT Start)</translation>
        </message>
        <message>
            <source>node {0} is in {1}: the valve applies a setpoint from the bus only in DEVICE_MODE_ACTIVE — enable it first (Valve status → Commissioning: control word 08h→09h→0Bh→0Fh)</source>
            <translation>Knoten {0} ist in {1}: Das Ventil übernimmt einen Sollwert vom Bus nur in DEVICE_MODE_ACTIVE — geben Sie es zuerst frei (Ventilstatus → Inbetriebnahme: Steuerwort 08h→09h→0Bh→0Fh)</translation>
        </message>
        <message>
            <source>node {0}: RPDO1 is switched off (0x1400/1 = {1}, bit 31): clear bit 31 to drive the setpoint from prm9tool</source>
            <translation>Knoten {0}: RPDO1 ist ausgeschaltet (0x1400/1 = {1}, Bit 31): Löschen Sie Bit 31, um den Sollwert aus prm9tool vorzugeben</translation>
        </message>
        <message>
            <source>node {0}: RPDO1 is synchronous (0x1400/2 = {1}), so the setpoint would wait for a SYNC: set 0x1400/2 to 255 (the delivery state)</source>
            <translation>Knoten {0}: RPDO1 ist synchron (0x1400/2 = {1}), der Sollwert würde auf ein SYNC warten: Setzen Sie 0x1400/2 auf 255 (Auslieferungszustand)</translation>
        </message>
        <message>
            <source>node {0}: RPDO1 maps {1}, not the setpoint 0x6300/0x6380</source>
            <translation>Knoten {0}: RPDO1 bildet {1} ab, nicht den Sollwert 0x6300/0x6380</translation>
        </message>
        <message>
            <source>The valve restarted at another address or bit rate: go online with it there.</source>
            <translation>Das Ventil ist mit anderer Adresse oder Bitrate neu gestartet: Gehen Sie dort mit ihm online.</translation>
        </message>
        <message>
            <source>The link could not keep the test's sample rate.</source>
            <translation>Die Verbindung konnte die Abtastrate des Tests nicht halten.</translation>
        </message>
        <message>
            <source>Node ID assignment (LSS) did not complete.</source>
            <translation>Die Vergabe der Node-ID (LSS) wurde nicht abgeschlossen.</translation>
        </message>
        <message>
            <source>The bit rate cannot be found without transmitting on this adapter.</source>
            <translation>Mit diesem Adapter lässt sich die Bitrate nicht ermitteln, ohne zu senden.</translation>
        </message>
        <message>
            <source>No bit rate gave valid frames.</source>
            <translation>Bei keiner Bitrate kamen gültige Frames an.</translation>
        </message>
        <message>
            <source>The acceptance profile cannot be used.</source>
            <translation>Das Abnahmeprofil kann nicht verwendet werden.</translation>
        </message>
        <message>
            <source>the valve stays in {0}: error 0x{1} ({2}) is still present — remove its cause, then enable again (the control word 08h resets the fault once it is gone)</source>
            <translation>Das Ventil bleibt in {0}: Fehler 0x{1} ({2}) liegt noch an — beseitigen Sie die Ursache und geben Sie es dann erneut frei (das Steuerwort 08h setzt den Fehler zurück, sobald er behoben ist)</translation>
        </message>
        <message>
            <source>the valve stays in {0} with no error present: it did not take the fault reset — write the control word 00h, then enable again</source>
            <translation>Das Ventil bleibt in {0}, obwohl kein Fehler anliegt: es hat den Fehler-Reset nicht angenommen — schreiben Sie das Steuerwort 00h und geben Sie es dann erneut frei</translation>
        </message>
        <message>
            <source>the valve is NMT stopped and takes no control word: send NMT start first</source>
            <translation>Das Ventil ist NMT-gestoppt und nimmt kein Steuerwort an: senden Sie zuerst NMT-Start</translation>
        </message>
        <message>
            <source>the valve is still starting up (about 2 s after power-up): enable it then</source>
            <translation>Das Ventil startet noch (etwa 2 s nach dem Einschalten): geben Sie es danach frei</translation>
        </message>
        <message>
            <source>the valve is in NOT_READY after the control word 08h → 09h → 0Bh → 0Fh: it has not finished starting up (about 2 s after power-up) — wait until it has, then enable again; if it stays in NOT_READY, check its supply voltage (19.2 … 28 V)</source>
            <translation>Das Ventil ist nach dem Steuerwort 08h → 09h → 0Bh → 0Fh in NOT_READY: es hat seinen Start noch nicht beendet (etwa 2 s nach dem Einschalten) — warten Sie, bis es gestartet ist, und geben Sie es dann erneut frei; bleibt es in NOT_READY, prüfen Sie seine Versorgungsspannung (19,2 … 28 V)</translation>
        </message>
        <message>
            <source>the valve is in {0} after the control word 08h → 09h → 0Bh → 0Fh, not DEVICE_MODE_ACTIVE</source>
            <translation>Das Ventil ist nach dem Steuerwort 08h → 09h → 0Bh → 0Fh in {0}, nicht in DEVICE_MODE_ACTIVE</translation>
        </message>
        <message>
            <source>the valve stays in DEVICE_MODE_ACTIVE after the control word 0Fh → 0Bh → 09h → 08h and still follows its setpoint — make the hydraulics safe, then look for another CANopen master enabling it or restart the valve</source>
            <translation>Das Ventil bleibt nach dem Steuerwort 0Fh → 0Bh → 09h → 08h in DEVICE_MODE_ACTIVE und folgt weiter seinem Sollwert – bringen Sie die Hydraulik in einen sicheren Zustand und suchen Sie dann nach einem anderen CANopen-Master, der es freigibt, oder starten Sie das Ventil neu</translation>
        </message>
        <message>
            <source>The valve has no birth certificate in the history.</source>
            <translation>Das Ventil hat keine Geburtsurkunde im Verlauf.</translation>
        </message>
        <message>
            <source>The valve stopped sending its measuring points.</source>
            <translation>Das Ventil sendet seine Messpunkte nicht mehr.</translation>
        </message>
    </context>
    <context>
        <name>EventTableModel</name>
        <message>
            <source>Time (s)</source>
            <translation>Zeit (s)</translation>
        </message>
        <message>
            <source>Node</source>
            <translation>Knoten</translation>
        </message>
        <message>
            <source>Kind</source>
            <translation>Art</translation>
        </message>
        <message>
            <source>What</source>
            <translation>Was</translation>
        </message>
        <message>
            <source>Frames</source>
            <translation>Frames</translation>
        </message>
    </context>
    <context>
        <name>FileWorkflow</name>
        <message>
            <source>untitled</source>
            <translation>unbenannt</translation>
        </message>
        <message>
            <source>Unsaved changes</source>
            <translation>Ungespeicherte Änderungen</translation>
        </message>
        <message>
            <source>The parameters in “{0}” have been changed. Save the changes?</source>
            <translation>Die Parameter in „{0}“ wurden geändert. Änderungen speichern?</translation>
        </message>
        <message>
            <source>New parameter set for {0}</source>
            <translation>Neuer Parametersatz für {0}</translation>
        </message>
        <message>
            <source>Open parameter file</source>
            <translation>Parameterdatei öffnen</translation>
        </message>
        <message>
            <source>Parameter files (*.prm);;All files (*)</source>
            <translation>Parameterdateien (*.prm);;Alle Dateien (*)</translation>
        </message>
        <message>
            <source>File not found</source>
            <translation>Datei nicht gefunden</translation>
        </message>
        <message>
            <source>“{0}” no longer exists; it was removed from the list.</source>
            <translation>„{0}“ existiert nicht mehr; die Datei wurde aus der Liste entfernt.</translation>
        </message>
        <message>
            <source>Opening {0} cancelled</source>
            <translation>Öffnen von {0} abgebrochen</translation>
        </message>
        <message>
            <source>Backup copy saved as {0}; {1} stays the open document</source>
            <translation>Sicherungskopie als {0} gespeichert; geöffnet bleibt {1}</translation>
        </message>
        <message>
            <source>Still reading {0}</source>
            <translation>{0} wird noch gelesen</translation>
        </message>
        <message>
            <source>Cannot open “{0}”</source>
            <translation>„{0}“ kann nicht geöffnet werden</translation>
        </message>
        <message>
            <source>Opened {0}</source>
            <translation>{0} geöffnet</translation>
        </message>
        <message>
            <source>Opened with warnings</source>
            <translation>Mit Warnungen geöffnet</translation>
        </message>
        <message numerus="yes">
            <source>“{0}” was opened; %n warning(s) were found.</source>
            <translation>
                <numerusform>„{0}“ wurde geöffnet; %n Warnung gefunden.</numerusform>
                <numerusform>„{0}“ wurde geöffnet; %n Warnungen gefunden.</numerusform>
            </translation>
        </message>
        <message>
            <source>Reading “{0}”…</source>
            <translation>„{0}“ wird gelesen…</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
        <message>
            <source>Save parameter file</source>
            <translation>Parameterdatei speichern</translation>
        </message>
        <message>
            <source>Parameter files (*.prm)</source>
            <translation>Parameterdateien (*.prm)</translation>
        </message>
        <message>
            <source>Cannot save “{0}”</source>
            <translation>„{0}“ kann nicht gespeichert werden</translation>
        </message>
        <message numerus="yes">
            <source>(marked: %n rule(s) broken)</source>
            <translation>
                <numerusform>(gekennzeichnet: %n Regel verletzt)</numerusform>
                <numerusform>(gekennzeichnet: %n Regeln verletzt)</numerusform>
            </translation>
        </message>
        <message>
            <source>Save backup copy</source>
            <translation>Sicherungskopie speichern</translation>
        </message>
        <message>
            <source>Saved {0}</source>
            <translation>{0} gespeichert</translation>
        </message>
        <message numerus="yes">
            <source>%n more problem(s) in the details.</source>
            <translation>
                <numerusform>%n weiteres Problem in den Details.</numerusform>
                <numerusform>%n weitere Probleme in den Details.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>… and %n more problem(s).</source>
            <translation>
                <numerusform>… und %n weiteres Problem.</numerusform>
                <numerusform>… und %n weitere Probleme.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>FlowPage</name>
        <message>
            <source>process setpoint steps %1 → %2 → %1 % with the process controller proportional only, %3 s each</source>
            <translation>Prozesssollwert-Sprünge %1 → %2 → %1 % mit rein proportionalem Prozessregler, je %3 s</translation>
        </message>
        <message>
            <source>Flow characteristic</source>
            <translation>Durchflusskennlinie</translation>
        </message>
        <message>
            <source>spool opening [%]</source>
            <translation>Schieberöffnung [%]</translation>
        </message>
        <message>
            <source>actuator velocity [%/s]</source>
            <translation>Geschwindigkeit des Antriebs [%/s]</translation>
        </message>
        <message>
            <source>measured</source>
            <translation>gemessen</translation>
        </message>
        <message>
            <source>with the proposed offsets (preview)</source>
            <translation>mit den vorgeschlagenen Offsets (Vorschau)</translation>
        </message>
        <message>
            <source>Flow gain %1 %/s per % of opening, dead band %2 … %3 % (width %4 %). Proposed offsets on the control deviation (process Kp %5): %6.</source>
            <translation>Durchflussverstärkung %1 %/s je % Öffnung, Totband %2 … %3 % (Breite %4 %). Vorgeschlagene Offsets der Regelabweichung (Prozess-Kp %5): %6.</translation>
        </message>
        <message>
            <source>Offsets from the flow characteristic</source>
            <translation>Offsets aus der Durchflusskennlinie</translation>
        </message>
        <message>
            <source>Step around the operating point:</source>
            <translation>Sprung um den Arbeitspunkt:</translation>
        </message>
        <message>
            <source>Operating point:</source>
            <translation>Arbeitspunkt:</translation>
        </message>
        <message>
            <source>Duration of each step:</source>
            <translation>Dauer jedes Sprungs:</translation>
        </message>
        <message>
            <source>Measure the flow characteristic</source>
            <translation>Durchflusskennlinie messen</translation>
        </message>
        <message>
            <source>Apply the proposed offsets</source>
            <translation>Vorgeschlagene Offsets übernehmen</translation>
        </message>
    </context>
    <context>
        <name>GeneratorPanel</name>
        <message>
            <source>Step</source>
            <translation>Sprung</translation>
        </message>
        <message>
            <source>Square</source>
            <translation>Rechteck</translation>
        </message>
        <message>
            <source>Sine</source>
            <translation>Sinus</translation>
        </message>
        <message>
            <source>Waveform</source>
            <translation>Signalform</translation>
        </message>
        <message>
            <source>Period</source>
            <translation>Periode</translation>
        </message>
        <message>
            <source>Amplitude</source>
            <translation>Amplitude</translation>
        </message>
        <message>
            <source>Offset</source>
            <translation>Offset</translation>
        </message>
        <message>
            <source>Step and square: height of the step above the offset. Sine: peak value. In % of the setpoint range.</source>
            <translation>Sprung und Rechteck: Höhe des Sprungs über dem Offset. Sinus: Scheitelwert. In % des Sollwertbereichs.</translation>
        </message>
        <message>
            <source>Stop generator</source>
            <translation>Generator stoppen</translation>
        </message>
        <message>
            <source>Start generator</source>
            <translation>Generator starten</translation>
        </message>
        <message>
            <source>Generator</source>
            <translation>Generator</translation>
        </message>
        <message>
            <source>Setpoint generator: drives the valve's setpoint for tuning (manual §8.7.2)</source>
            <translation>Sollwertgenerator: gibt den Sollwert des Ventils zum Einstellen der Regler vor (Handbuch §8.7.2)</translation>
        </message>
    </context>
    <context>
        <name>GeneratorSettings</name>
        <message>
            <source>The generator period must be longer than 0 s.</source>
            <translation>Die Periode des Generators muss länger als 0 s sein.</translation>
        </message>
        <message>
            <source>The waveform reaches {0} … {1} %; the setpoint must stay within {2} … {3} %.</source>
            <translation>Die Kurvenform erreicht {0} … {1} %; der Sollwert muss zwischen {2} … {3} % bleiben.</translation>
        </message>
    </context>
    <context>
        <name>GeneratorStart</name>
        <message>
            <source>Setpoint generator</source>
            <translation>Sollwertgenerator</translation>
        </message>
        <message>
            <source>The generator will drive the valve's setpoint and the valve will move.
Make sure the machine is safe to move. Start the generator?</source>
            <translation>Der Generator steuert den Sollwert des Ventils und das Ventil wird sich bewegen.
Stellen Sie sicher, dass die Maschine sich gefahrlos bewegen kann. Generator starten?</translation>
        </message>
        <message>
            <source>The valve does not follow its setpoint: {0}

Enable it now (NMT start, control word 08h → 09h → 0Bh → 0Fh)?</source>
            <translation>Das Ventil folgt seinem Sollwert nicht: {0}

Jetzt freigeben (NMT Start, Steuerwort 08h → 09h → 0Bh → 0Fh)?</translation>
        </message>
    </context>
    <context>
        <name>Help</name>
        <message>
            <source>Home page</source>
            <translation>Homepage</translation>
        </message>
        <message>
            <source>No web browser could be started. The home page is {0}</source>
            <translation>Es konnte kein Webbrowser gestartet werden. Die Homepage ist {0}</translation>
        </message>
        <message>
            <source>unknown</source>
            <translation>unbekannt</translation>
        </message>
        <message>
            <source>{0} (single executable)</source>
            <translation>{0} (eigenständige Programmdatei)</translation>
        </message>
        <message>
            <source>commit</source>
            <translation>Revision</translation>
        </message>
        <message>
            <source>built</source>
            <translation>Erstellt</translation>
        </message>
    </context>
    <context>
        <name>HelpWindow</name>
        <message>
            <source>prm9tool help</source>
            <translation>prm9tool – Hilfe</translation>
        </message>
    </context>
    <context>
        <name>HidConfigurationDialog</name>
        <message>
            <source>HID configuration</source>
            <translation>HID-Konfiguration</translation>
        </message>
        <message>
            <source>Valves connected to this computer and emulated valves. Choose the one to communicate with.</source>
            <translation>An diesen Computer angeschlossene und emulierte Ventile. Wählen Sie das Ventil für die Kommunikation.</translation>
        </message>
        <message>
            <source>Connection</source>
            <translation>Verbindung</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Typschlüssel</translation>
        </message>
        <message>
            <source>Serial number</source>
            <translation>Seriennummer</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Beschreibung</translation>
        </message>
        <message>
            <source>Add emulated valve…</source>
            <translation>Emuliertes Ventil hinzufügen…</translation>
        </message>
        <message>
            <source>Remove emulated valve</source>
            <translation>Emuliertes Ventil entfernen</translation>
        </message>
        <message>
            <source>Refresh</source>
            <translation>Aktualisieren</translation>
        </message>
        <message>
            <source>Looking for valves…</source>
            <translation>Ventile werden gesucht…</translation>
        </message>
        <message>
            <source>Listing the valves failed: {0}</source>
            <translation>Auflisten der Ventile fehlgeschlagen: {0}</translation>
        </message>
        <message>
            <source>emulated {0}, serial {1}</source>
            <translation>emuliertes Ventil {0}, Seriennummer {1}</translation>
        </message>
        <message>
            <source>cannot be used (remove it): {0}</source>
            <translation>nicht verwendbar (bitte entfernen): {0}</translation>
        </message>
        <message>
            <source>Emulated valve</source>
            <translation>Emuliertes Ventil</translation>
        </message>
        <message>
            <source>USB</source>
            <translation>USB</translation>
        </message>
    </context>
    <context>
        <name>HistoryPolicy</name>
        <message>
            <source>Upload refused</source>
            <translation>Hochladen abgelehnt</translation>
        </message>
        <message>
            <source>The history database cannot record this upload, and the setting says to refuse uploads then. Nothing was written to the valve.</source>
            <translation>Die Verlaufsdatenbank kann dieses Hochladen nicht aufzeichnen, und die Einstellung verlangt, dann nicht hochzuladen. In das Ventil wurde nichts geschrieben.</translation>
        </message>
        <message>
            <source>History database unavailable</source>
            <translation>Verlaufsdatenbank nicht erreichbar</translation>
        </message>
        <message>
            <source>The history database cannot record this upload. Upload anyway and keep the record on this computer until the database is back?

Yes uploads and queues the record; No uploads nothing.</source>
            <translation>Die Verlaufsdatenbank kann dieses Hochladen nicht aufzeichnen. Trotzdem hochladen und den Eintrag auf diesem Rechner aufbewahren, bis die Datenbank wieder erreichbar ist?

Ja lädt hoch und stellt den Eintrag in die Warteschlange; Nein lädt nichts hoch.</translation>
        </message>
    </context>
    <context>
        <name>HistorySettingsDialog</name>
        <message>
            <source>History database</source>
            <translation>Verlaufsdatenbank</translation>
        </message>
        <message>
            <source>ask before uploading</source>
            <translation>vor dem Hochladen fragen</translation>
        </message>
        <message>
            <source>refuse the upload (production line)</source>
            <translation>Hochladen ablehnen (Fertigungslinie)</translation>
        </message>
        <message>
            <source>upload and keep the record here until the database is back</source>
            <translation>hochladen und den Eintrag hier aufbewahren, bis die Datenbank wieder erreichbar ist</translation>
        </message>
        <message>
            <source>Empty: SQLite on this computer. A line of stations: postgresql+psycopg://user:password@server/database</source>
            <translation>Leer: SQLite auf diesem Rechner. Eine Linie von Stationen: postgresql+psycopg://benutzer:passwort@server/datenbank</translation>
        </message>
        <message>
            <source>Database:</source>
            <translation>Datenbank:</translation>
        </message>
        <message>
            <source>When it cannot be reached:</source>
            <translation>Wenn sie nicht erreichbar ist:</translation>
        </message>
    </context>
    <context>
        <name>HistoryTableModel</name>
        <message>
            <source>No.</source>
            <translation>Nr.</translation>
        </message>
        <message>
            <source>Time (UTC)</source>
            <translation>Zeit (UTC)</translation>
        </message>
        <message>
            <source>Operation</source>
            <translation>Vorgang</translation>
        </message>
        <message>
            <source>Outcome</source>
            <translation>Ergebnis</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Typenschlüssel</translation>
        </message>
        <message>
            <source>What was done</source>
            <translation>Was getan wurde</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>User, station, link</source>
            <translation>Benutzer, Station, Verbindung</translation>
        </message>
        <message>
            <source>ok</source>
            <translation>ok</translation>
        </message>
        <message>
            <source>passed</source>
            <translation>bestanden</translation>
        </message>
        <message>
            <source>failed</source>
            <translation>nicht bestanden</translation>
        </message>
        <message>
            <source>verification-failed</source>
            <translation>Prüfung fehlgeschlagen</translation>
        </message>
        <message>
            <source>store-failed</source>
            <translation>Speichern fehlgeschlagen</translation>
        </message>
        <message>
            <source>communication-error</source>
            <translation>Kommunikationsfehler</translation>
        </message>
        <message>
            <source>type-mismatch</source>
            <translation>falscher Ventiltyp</translation>
        </message>
        <message>
            <source>error</source>
            <translation>Fehler</translation>
        </message>
        <message>
            <source>dry-run</source>
            <translation>Probelauf</translation>
        </message>
        <message>
            <source>downloaded</source>
            <translation>heruntergeladen</translation>
        </message>
        <message>
            <source>proposed</source>
            <translation>Vorschlag</translation>
        </message>
        <message>
            <source>targets-missed</source>
            <translation>Ziele verfehlt</translation>
        </message>
        <message>
            <source>explained</source>
            <translation>erklärt</translation>
        </message>
        <message>
            <source>not-explained</source>
            <translation>nicht erklärt</translation>
        </message>
        <message>
            <source>no-drift</source>
            <translation>keine Drift</translation>
        </message>
        <message>
            <source>drifted</source>
            <translation>Drift festgestellt</translation>
        </message>
        <message>
            <source>backup</source>
            <translation>Sicherung</translation>
        </message>
        <message>
            <source>write</source>
            <translation>Schreiben</translation>
        </message>
        <message>
            <source>verify</source>
            <translation>Prüfen</translation>
        </message>
        <message>
            <source>store</source>
            <translation>Speichern</translation>
        </message>
        <message>
            <source>download</source>
            <translation>Herunterladen</translation>
        </message>
        <message>
            <source>upload</source>
            <translation>Hochladen</translation>
        </message>
        <message>
            <source>batch-upload</source>
            <translation>Hochladen (--batch)</translation>
        </message>
        <message>
            <source>online-edits</source>
            <translation>Online-Änderungen</translation>
        </message>
        <message>
            <source>restore-factory</source>
            <translation>Werkseinstellungen</translation>
        </message>
        <message>
            <source>characterization</source>
            <translation>Endprüfung</translation>
        </message>
        <message>
            <source>compare-apply</source>
            <translation>Vergleich übernommen</translation>
        </message>
        <message>
            <source>history-restore</source>
            <translation>aus Verlauf wiederhergestellt</translation>
        </message>
        <message>
            <source>tuning-accepted</source>
            <translation>Einstellung übernommen</translation>
        </message>
        <message>
            <source>restart-verify</source>
            <translation>Prüfung durch Neustart</translation>
        </message>
        <message>
            <source>restart</source>
            <translation>Neustart</translation>
        </message>
        <message>
            <source>autotune</source>
            <translation>Autotune</translation>
        </message>
        <message>
            <source>frequency-response</source>
            <translation>Frequenzgang</translation>
        </message>
        <message>
            <source>report-saved</source>
            <translation>Prüfbericht gespeichert</translation>
        </message>
        <message>
            <source>twin</source>
            <translation>Zwilling</translation>
        </message>
        <message>
            <source>signature</source>
            <translation>Vergleich mit Geburtsurkunde</translation>
        </message>
        <message>
            <source>Marked {0}: records of another valve type than {1} under this serial number — another valve (emulated valves of two runs of the program may share a serial number); compare or restore them only knowingly.</source>
            <translation>Mit {0} markiert: Einträge eines anderen Ventiltyps als {1} unter dieser Seriennummer — ein anderes Ventil (emulierte Ventile zweier Programmläufe können eine Seriennummer teilen); nur bewusst vergleichen oder wiederherstellen.</translation>
        </message>
        <message numerus="yes">
            <source>%n more</source>
            <translation>
                <numerusform>%n weiterer</numerusform>
                <numerusform>%n weitere</numerusform>
            </translation>
        </message>
        <message>
            <source>position loop</source>
            <translation>Lageregelkreis</translation>
        </message>
        <message>
            <source>process loop</source>
            <translation>Prozessregelkreis</translation>
        </message>
        <message>
            <source>profile {0}</source>
            <translation>Profil {0}</translation>
        </message>
        <message>
            <source>failed: {0}</source>
            <translation>nicht bestanden: {0}</translation>
        </message>
        <message>
            <source>PDF {0}</source>
            <translation>PDF {0}</translation>
        </message>
        <message>
            <source>proposed {0}</source>
            <translation>vorgeschlagen {0}</translation>
        </message>
        <message>
            <source>misses the targets</source>
            <translation>verfehlt die Ziele</translation>
        </message>
        <message>
            <source>not found</source>
            <translation>nicht gefunden</translation>
        </message>
        <message>
            <source>Read from the valve</source>
            <translation>Aus dem Ventil gelesen</translation>
        </message>
        <message>
            <source>Written, verified and stored</source>
            <translation>Geschrieben, geprüft und gespeichert</translation>
        </message>
        <message>
            <source>Written by --batch</source>
            <translation>Mit --batch geschrieben</translation>
        </message>
        <message>
            <source>Stored (Valve → Store in valve)</source>
            <translation>Gespeichert (Ventil → Im Ventil speichern)</translation>
        </message>
        <message>
            <source>Values changed online, stored</source>
            <translation>Online geänderte Werte gespeichert</translation>
        </message>
        <message>
            <source>Backup of the valve's values</source>
            <translation>Sicherung der Werte des Ventils</translation>
        </message>
        <message>
            <source>Factory values restored</source>
            <translation>Werkseinstellungen wiederhergestellt</translation>
        </message>
        <message>
            <source>Test report</source>
            <translation>Prüfbericht</translation>
        </message>
        <message>
            <source>Values from a compared file, written online</source>
            <translation>Werte aus einer verglichenen Datei, online geschrieben</translation>
        </message>
        <message>
            <source>Values from the history, written online</source>
            <translation>Werte aus dem Verlauf, online geschrieben</translation>
        </message>
        <message>
            <source>Tuning accepted, written online</source>
            <translation>Einstellung übernommen, online geschrieben</translation>
        </message>
        <message>
            <source>Restarted and read back (Valve → Verify by restart…)</source>
            <translation>Neu gestartet und zurückgelesen (Ventil → Durch Neustart prüfen…)</translation>
        </message>
        <message>
            <source>Restarted (Valve → Restart valve)</source>
            <translation>Neu gestartet (Ventil → Ventil neu starten)</translation>
        </message>
        <message>
            <source>Autotune run</source>
            <translation>Autotune-Lauf</translation>
        </message>
        <message>
            <source>Frequency response measured</source>
            <translation>Frequenzgang gemessen</translation>
        </message>
        <message>
            <source>Test report saved</source>
            <translation>Prüfbericht gespeichert</translation>
        </message>
        <message>
            <source>Twin fitted (--fit-twin)</source>
            <translation>Digitaler Zwilling ermittelt (--fit-twin)</translation>
        </message>
        <message>
            <source>Compared with the birth certificate (--signature)</source>
            <translation>Mit der Geburtsurkunde verglichen (--signature)</translation>
        </message>
        <message>
            <source>stored with 0x1010</source>
            <translation>mit 0x1010 gespeichert</translation>
        </message>
        <message>
            <source>kept by the valve as written (it has no store command)</source>
            <translation>vom Ventil wie geschrieben behalten (es hat keinen Speicherbefehl)</translation>
        </message>
        <message>
            <source>verified after a restart</source>
            <translation>nach einem Neustart geprüft</translation>
        </message>
        <message>
            <source>going online</source>
            <translation>beim Online-Gehen</translation>
        </message>
        <message>
            <source>Valve → Download</source>
            <translation>Ventil → Herunterladen</translation>
        </message>
        <message>
            <source>Compare with valve</source>
            <translation>Mit Ventil vergleichen</translation>
        </message>
        <message>
            <source>Valve → Upload</source>
            <translation>Ventil → Hochladen</translation>
        </message>
        <message>
            <source>chosen in the compare view</source>
            <translation>in der Vergleichsansicht gewählt</translation>
        </message>
        <message>
            <source>chosen per parameter going online</source>
            <translation>beim Online-Gehen je Parameter gewählt</translation>
        </message>
        <message>
            <source>a history record restored</source>
            <translation>ein Eintrag aus dem Verlauf wiederhergestellt</translation>
        </message>
    </context>
    <context>
        <name>HistoryWindow</name>
        <message>
            <source>History</source>
            <translation>Verlauf</translation>
        </message>
        <message>
            <source>serial number</source>
            <translation>Seriennummer</translation>
        </message>
        <message>
            <source>Show</source>
            <translation>Anzeigen</translation>
        </message>
        <message>
            <source>Valve serial number:</source>
            <translation>Seriennummer des Ventils:</translation>
        </message>
        <message>
            <source>Compare the two selected records</source>
            <translation>Die zwei gewählten Einträge vergleichen</translation>
        </message>
        <message>
            <source>Restore into the document</source>
            <translation>In das Dokument übernehmen</translation>
        </message>
        <message>
            <source>Restore to the valve</source>
            <translation>In das Ventil zurückschreiben</translation>
        </message>
        <message>
            <source>Export…</source>
            <translation>Exportieren…</translation>
        </message>
        <message>
            <source>Database…</source>
            <translation>Datenbank…</translation>
        </message>
        <message>
            <source>Type a valve's serial number.</source>
            <translation>Seriennummer eines Ventils eingeben.</translation>
        </message>
        <message>
            <source>Reading the history…</source>
            <translation>Verlauf wird gelesen…</translation>
        </message>
        <message numerus="yes">
            <source>%n record(s) in {0}</source>
            <translation>
                <numerusform>%n Eintrag in {0}</numerusform>
                <numerusform>%n Einträge in {0}</numerusform>
            </translation>
        </message>
        <message>
            <source>This record holds no parameter set (the operation did not change the valve's stored parameters).</source>
            <translation>Dieser Eintrag enthält keinen Parametersatz (der Vorgang hat die gespeicherten Parameter des Ventils nicht geändert).</translation>
        </message>
        <message>
            <source>No. {0}, {1}</source>
            <translation>Nr. {0}, {1}</translation>
        </message>
        <message>
            <source>Go online with valve {0} first: a record is restored only into the valve it was recorded from.</source>
            <translation>Zuerst mit Ventil {0} online gehen: Ein Eintrag wird nur in das Ventil zurückgeschrieben, von dem er stammt.</translation>
        </message>
        <message>
            <source>Export record</source>
            <translation>Eintrag exportieren</translation>
        </message>
        <message>
            <source>Parameter files (*.prm);;CSV tables (*.csv)</source>
            <translation>Parameterdateien (*.prm);;CSV-Tabellen (*.csv)</translation>
        </message>
        <message>
            <source>The record was not exported.</source>
            <translation>Der Eintrag wurde nicht exportiert.</translation>
        </message>
    </context>
    <context>
        <name>LinearizationDialog</name>
        <message>
            <source>Input X (%)</source>
            <translation>Eingang X (%)</translation>
        </message>
        <message>
            <source>Output Y (%)</source>
            <translation>Ausgang Y (%)</translation>
        </message>
        <message>
            <source>Reset to a straight line</source>
            <translation>Auf eine Gerade zurücksetzen</translation>
        </message>
        <message>
            <source>Input (%)</source>
            <translation>Eingang (%)</translation>
        </message>
        <message>
            <source>Output (%)</source>
            <translation>Ausgang (%)</translation>
        </message>
        <message>
            <source>Linearization point %1</source>
            <translation>Linearisierungspunkt %1</translation>
        </message>
        <message>
            <source>Linearization reset to a straight line</source>
            <translation>Linearisierung auf eine Gerade zurückgesetzt</translation>
        </message>
    </context>
    <context>
        <name>LinkGuard</name>
        <message>
            <source>The connection will move</source>
            <translation>Die Verbindung wird sich ändern</translation>
        </message>
        <message>
            <source>The node-ID switch is at position {0}: the switches decide node ID and bit rate (manual table 7-17), so this change does not move the valve; it stays at node {1}.</source>
            <translation>Der Node-ID-Schalter steht auf Stellung {0}: Die Schalter bestimmen Node-ID und Bitrate (Handbuch, Tabelle 7-17), diese Änderung verschiebt das Ventil also nicht; es bleibt Knoten {1}.</translation>
        </message>
        <message>
            <source>The node-ID switch is at position 1 (LSS): an LSS master sets node ID and bit rate (manual table 7-17; Communication → CAN bus). NODEID and BITRATE apply at position 0 only, so this change does not move the valve.</source>
            <translation>Der Node-ID-Schalter steht auf Stellung 1 (LSS): Node-ID und Bitrate setzt ein LSS-Master (Handbuch Tabelle 7-17; Kommunikation → CAN-Bus). NODEID und BITRATE gelten nur in Stellung 0, diese Änderung verschiebt das Ventil also nicht.</translation>
        </message>
        <message>
            <source>After the valve's next power-up or restart it answers at node {0}, {1}. Store the change and restart the valve from prm9tool (Valve → Restart valve): prm9tool then finds it there again — where it cannot change the adapter's bit rate itself (SocketCAN), it says how. After a power-up, find it under Communication → CAN bus (node {0}, bit rate {1}).</source>
            <translation>Nach dem nächsten Einschalten oder Neustart antwortet das Ventil als Knoten {0}, {1}. Speichern Sie die Änderung und starten Sie das Ventil aus prm9tool neu (Ventil → Ventil neu starten): prm9tool findet es dann dort wieder — wo es die Bitrate des Adapters nicht selbst ändern kann (SocketCAN), sagt es, wie. Nach einem Einschalten finden Sie es unter Kommunikation → CAN-Bus (Knoten {0}, Bitrate {1}).</translation>
        </message>
    </context>
    <context>
        <name>LssPanel</name>
        <message>
            <source>Devices without a node ID (node-ID switch at 1: LSS)</source>
            <translation>Geräte ohne Node-ID (Node-ID-Schalter auf 1: LSS)</translation>
        </message>
        <message>
            <source>Serial</source>
            <translation>Seriennummer</translation>
        </message>
        <message>
            <source>Device</source>
            <translation>Gerät</translation>
        </message>
        <message>
            <source>Vendor ID</source>
            <translation>Hersteller-ID</translation>
        </message>
        <message>
            <source>Product code</source>
            <translation>Produktcode</translation>
        </message>
        <message>
            <source>Revision</source>
            <translation>Revision</translation>
        </message>
        <message>
            <source>Look for devices without a node ID</source>
            <translation>Geräte ohne Node-ID suchen</translation>
        </message>
        <message>
            <source>Assign node ID…</source>
            <translation>Node-ID zuweisen…</translation>
        </message>
        <message>
            <source>Assign node IDs to all…</source>
            <translation>Allen Node-IDs zuweisen…</translation>
        </message>
        <message>
            <source>Looking for devices without a node ID (LSS Fastscan)…</source>
            <translation>Suche Geräte ohne Node-ID (LSS-Fastscan)…</translation>
        </message>
        <message>
            <source>PRM9</source>
            <translation>PRM9</translation>
        </message>
        <message>
            <source>not a PRM9</source>
            <translation>kein PRM9</translation>
        </message>
        <message numerus="yes">
            <source>%n device(s) without a node ID.</source>
            <translation>
                <numerusform>%n Gerät ohne Node-ID.</numerusform>
                <numerusform>%n Geräte ohne Node-ID.</numerusform>
            </translation>
        </message>
        <message>
            <source>No device without a node ID answered: every device has one, or none is at node-ID switch 1, or the bus runs at another bit rate.</source>
            <translation>Kein Gerät ohne Node-ID hat geantwortet: Jedes Gerät hat eine, keines steht mit dem Node-ID-Schalter auf 1, oder der Bus läuft mit einer anderen Bitrate.</translation>
        </message>
        <message>
            <source>Assign node ID</source>
            <translation>Node-ID zuweisen</translation>
        </message>
        <message>
            <source>Node ID for serial {0} (1…127; stored in the valve, used from now on and after every power-up):</source>
            <translation>Node-ID für Seriennummer {0} (1…127; im Ventil gespeichert, ab sofort und nach jedem Einschalten gültig):</translation>
        </message>
        <message>
            <source>Node ID {0} is taken: a node answers there. Choose another one.</source>
            <translation>Node-ID {0} ist vergeben: Dort antwortet ein Knoten. Wählen Sie eine andere.</translation>
        </message>
        <message>
            <source>Giving serial {0} node ID {1} and storing it…</source>
            <translation>Seriennummer {0} erhält Node-ID {1}, sie wird gespeichert…</translation>
        </message>
        <message>
            <source>Assign node IDs to all</source>
            <translation>Allen Node-IDs zuweisen</translation>
        </message>
        <message>
            <source>First node ID: the {0} valves get consecutive free node IDs from it, in the order of their serial numbers (stored in each valve):</source>
            <translation>Erste Node-ID: Die {0} Ventile erhalten ab ihr fortlaufende freie Node-IDs, in der Reihenfolge ihrer Seriennummern (in jedem Ventil gespeichert):</translation>
        </message>
        <message>
            <source>From node ID {0} on there are only {1} free node IDs for {2} valves.</source>
            <translation>Ab Node-ID {0} gibt es nur {1} freie Node-IDs für {2} Ventile.</translation>
        </message>
        <message>
            <source>Giving node IDs: {0}…</source>
            <translation>Node-IDs werden vergeben: {0}…</translation>
        </message>
        <message>
            <source>Given and stored: {0}. Searching the bus again…</source>
            <translation>Vergeben und gespeichert: {0}. Der Bus wird erneut durchsucht…</translation>
        </message>
        <message>
            <source>Serial {0} answers as {1} (stored). Going online with it…</source>
            <translation>Seriennummer {0} antwortet als {1} (gespeichert). Online-Verbindung wird aufgebaut…</translation>
        </message>
    </context>
    <context>
        <name>MainActions</name>
        <message>
            <source>&amp;New…</source>
            <translation>&amp;Neu…</translation>
        </message>
        <message>
            <source>New parameter set from a valve type key</source>
            <translation>Neuer Parametersatz aus einem Ventil-Typschlüssel</translation>
        </message>
        <message>
            <source>&amp;Open…</source>
            <translation>Ö&amp;ffnen…</translation>
        </message>
        <message>
            <source>Open a parameter file (*.prm)</source>
            <translation>Parameterdatei (*.prm) öffnen</translation>
        </message>
        <message>
            <source>&amp;Save</source>
            <translation>&amp;Speichern</translation>
        </message>
        <message>
            <source>Save the parameter file (*.prm)</source>
            <translation>Parameterdatei (*.prm) speichern</translation>
        </message>
        <message>
            <source>Save &amp;As…</source>
            <translation>Speichern &amp;unter…</translation>
        </message>
        <message>
            <source>Save the parameters under another name</source>
            <translation>Parameter unter einem anderen Namen speichern</translation>
        </message>
        <message>
            <source>Save bac&amp;kup copy…</source>
            <translation>Sicherungs&amp;kopie speichern…</translation>
        </message>
        <message>
            <source>Save a copy of the parameters to another file; you keep working on this one</source>
            <translation>Eine Kopie der Parameter in eine andere Datei speichern; Sie arbeiten in dieser weiter</translation>
        </message>
        <message>
            <source>&amp;Undo</source>
            <translation>&amp;Rückgängig</translation>
        </message>
        <message>
            <source>Undo the last change</source>
            <translation>Letzte Änderung rückgängig machen</translation>
        </message>
        <message>
            <source>&amp;Redo</source>
            <translation>&amp;Wiederherstellen</translation>
        </message>
        <message>
            <source>Redo the change undone last</source>
            <translation>Zuletzt rückgängig gemachte Änderung wiederherstellen</translation>
        </message>
        <message>
            <source>&amp;Print…</source>
            <translation>&amp;Drucken…</translation>
        </message>
        <message>
            <source>Print the current parameter record</source>
            <translation>Aktuellen Parametersatz drucken</translation>
        </message>
        <message>
            <source>Object &amp;dictionary…</source>
            <translation>Objekt&amp;verzeichnis…</translation>
        </message>
        <message>
            <source>Read, and at Expert level write, any object of the valve</source>
            <translation>Jedes Objekt des Ventils lesen und, in der Expertenstufe, schreiben</translation>
        </message>
        <message>
            <source>Export &amp;DCF…</source>
            <translation>D&amp;CF exportieren…</translation>
        </message>
        <message>
            <source>Save the valve's CANopen configuration as a CiA 306 DCF (for a PLC configurator)</source>
            <translation>CANopen-Konfiguration des Ventils als CiA-306-DCF speichern (für einen SPS-Konfigurator)</translation>
        </message>
        <message>
            <source>&amp;Export PDF…</source>
            <translation>PDF &amp;exportieren…</translation>
        </message>
        <message>
            <source>Save the parameter record as PDF</source>
            <translation>Parameterprotokoll als PDF speichern</translation>
        </message>
        <message>
            <source>E&amp;xit</source>
            <translation>&amp;Beenden</translation>
        </message>
        <message>
            <source>Quit prm9tool</source>
            <translation>prm9tool beenden</translation>
        </message>
        <message>
            <source>&amp;Flow diagram</source>
            <translation>&amp;Ablaufdiagramm</translation>
        </message>
        <message>
            <source>Show the signal-flow diagram</source>
            <translation>Signalflussdiagramm anzeigen</translation>
        </message>
        <message>
            <source>&amp;Parameter list</source>
            <translation>&amp;Parameterliste</translation>
        </message>
        <message>
            <source>Show all parameters as a table</source>
            <translation>Alle Parameter als Tabelle anzeigen</translation>
        </message>
        <message>
            <source>&amp;Oscilloscope</source>
            <translation>&amp;Oszilloskop</translation>
        </message>
        <message>
            <source>Show values in real time (online mode only)</source>
            <translation>Werte in Echtzeit anzeigen (nur im Online-Modus)</translation>
        </message>
        <message>
            <source>&amp;CANopen window…</source>
            <translation>&amp;CANopen-Fenster…</translation>
        </message>
        <message>
            <source>CANopen settings of the valve</source>
            <translation>CANopen-Einstellungen des Ventils</translation>
        </message>
        <message>
            <source>&amp;Basic</source>
            <translation>&amp;Basis</translation>
        </message>
        <message>
            <source>Basic parameter settings</source>
            <translation>Grundlegende Parametereinstellungen</translation>
        </message>
        <message>
            <source>&amp;Expert…</source>
            <translation>&amp;Experte…</translation>
        </message>
        <message>
            <source>All settings including controllers and linearization</source>
            <translation>Alle Einstellungen einschließlich Regler und Linearisierung</translation>
        </message>
        <message>
            <source>&amp;Change Expert password…</source>
            <translation>Experten&amp;passwort ändern…</translation>
        </message>
        <message>
            <source>Valve &amp;selection…</source>
            <translation>Ventil&amp;auswahl…</translation>
        </message>
        <message>
            <source>Choose the valve configuration by its type key</source>
            <translation>Ventilkonfiguration über den Typschlüssel wählen</translation>
        </message>
        <message>
            <source>Valve s&amp;tatus…</source>
            <translation>Ventil&amp;status…</translation>
        </message>
        <message>
            <source>State, firmware, serial number and errors of the valve</source>
            <translation>Zustand, Firmware, Seriennummer und Fehler des Ventils</translation>
        </message>
        <message>
            <source>&amp;Upload to valve</source>
            <translation>In das Ventil &amp;hochladen</translation>
        </message>
        <message>
            <source>Write the parameters into the valve</source>
            <translation>Parameter in das Ventil schreiben</translation>
        </message>
        <message>
            <source>&amp;Download from valve</source>
            <translation>Aus dem Ventil he&amp;runterladen</translation>
        </message>
        <message>
            <source>Read the parameters of the valve into the program</source>
            <translation>Parameter des Ventils in das Programm lesen</translation>
        </message>
        <message>
            <source>St&amp;ore in valve</source>
            <translation>Im Ventil s&amp;peichern</translation>
        </message>
        <message>
            <source>Make the values the valve works with permanent: they stay after a restart</source>
            <translation>Die Werte, mit denen das Ventil arbeitet, dauerhaft speichern: Sie bleiben nach einem Neustart erhalten</translation>
        </message>
        <message>
            <source>Restore &amp;factory values…</source>
            <translation>&amp;Werkseinstellungen wiederherstellen…</translation>
        </message>
        <message>
            <source>Return the parameters to the factory values</source>
            <translation>Parameter auf die Werkseinstellungen zurücksetzen</translation>
        </message>
        <message>
            <source>&amp;Restart valve…</source>
            <translation>Ventil &amp;neu starten…</translation>
        </message>
        <message>
            <source>Restart the valve electronics (only with the hydraulics disconnected)</source>
            <translation>Ventilelektronik neu starten (nur bei getrennter Hydraulik)</translation>
        </message>
        <message>
            <source>&amp;Verify by restart…</source>
            <translation>&amp;Durch Neustart prüfen…</translation>
        </message>
        <message>
            <source>After an upload: restart the valve (hydraulics disconnected) and read back that it kept the values</source>
            <translation>Nach dem Hochladen: Ventil neu starten (Hydraulik getrennt) und zurücklesen, ob es die Werte behalten hat</translation>
        </message>
        <message>
            <source>&amp;HID configuration…</source>
            <translation>&amp;HID-Konfiguration…</translation>
        </message>
        <message>
            <source>Choose the valve to communicate with</source>
            <translation>Ventil für die Kommunikation wählen</translation>
        </message>
        <message>
            <source>&amp;CAN bus…</source>
            <translation>&amp;CAN-Bus…</translation>
        </message>
        <message>
            <source>Find the valves on a CAN bus and go online with one (CANopen)</source>
            <translation>Ventile an einem CAN-Bus suchen und mit einem online gehen (CANopen)</translation>
        </message>
        <message>
            <source>CAN &amp;trace…</source>
            <translation>CAN-&amp;Trace…</translation>
        </message>
        <message>
            <source>Record the CAN bus, or read a trace file in words</source>
            <translation>Den CAN-Bus aufzeichnen oder eine Trace-Datei im Klartext lesen</translation>
        </message>
        <message>
            <source>O&amp;nline mode</source>
            <translation>O&amp;nline-Modus</translation>
        </message>
        <message>
            <source>Connect to the valve</source>
            <translation>Mit dem Ventil verbinden</translation>
        </message>
        <message>
            <source>O&amp;ffline mode</source>
            <translation>O&amp;ffline-Modus</translation>
        </message>
        <message>
            <source>Disconnect from the valve</source>
            <translation>Verbindung zum Ventil trennen</translation>
        </message>
        <message>
            <source>&amp;Help</source>
            <translation>&amp;Hilfe</translation>
        </message>
        <message>
            <source>How to use prm9tool</source>
            <translation>Bedienung von prm9tool</translation>
        </message>
        <message>
            <source>Home&amp;page</source>
            <translation>Home&amp;page</translation>
        </message>
        <message>
            <source>Open the manufacturer's homepage</source>
            <translation>Homepage des Herstellers öffnen</translation>
        </message>
        <message>
            <source>&amp;About prm9tool</source>
            <translation>Ü&amp;ber prm9tool</translation>
        </message>
        <message>
            <source>Versions and contact</source>
            <translation>Versionen und Kontakt</translation>
        </message>
        <message>
            <source>Not while online: go offline first, then choose the valve to communicate with</source>
            <translation>Nicht im Online-Modus: erst offline gehen, dann das Ventil für die Kommunikation wählen</translation>
        </message>
        <message>
            <source>&amp;File</source>
            <translation>&amp;Datei</translation>
        </message>
        <message>
            <source>&amp;View</source>
            <translation>&amp;Ansicht</translation>
        </message>
        <message>
            <source>V&amp;alve</source>
            <translation>&amp;Ventil</translation>
        </message>
        <message>
            <source>&amp;Communication</source>
            <translation>&amp;Kommunikation</translation>
        </message>
        <message>
            <source>Open re&amp;cent</source>
            <translation>&amp;Zuletzt geöffnet</translation>
        </message>
        <message>
            <source>&amp;Access level</source>
            <translation>&amp;Berechtigungsstufe</translation>
        </message>
        <message>
            <source>&amp;Language</source>
            <translation>&amp;Sprache</translation>
        </message>
        <message>
            <source>Toolbar</source>
            <translation>Werkzeugleiste</translation>
        </message>
        <message>
            <source>Co&amp;mpare with file…</source>
            <translation>Mit Datei &amp;vergleichen…</translation>
        </message>
        <message>
            <source>Expor&amp;t EDS…</source>
            <translation>EDS e&amp;xportieren…</translation>
        </message>
        <message>
            <source>Save the valve type's CiA 306 EDS (for a PLC configurator)</source>
            <translation>CiA-306-EDS des Ventiltyps speichern (für einen SPS-Konfigurator)</translation>
        </message>
        <message>
            <source>Compare the parameters with a *.prm file, take chosen values</source>
            <translation>Die Parameter mit einer *.prm-Datei vergleichen, gewählte Werte übernehmen</translation>
        </message>
        <message>
            <source>&amp;Compare with valve</source>
            <translation>Mit Ventil &amp;vergleichen</translation>
        </message>
        <message>
            <source>Compare the document with the valve, apply chosen values</source>
            <translation>Das Dokument mit dem Ventil vergleichen, gewählte Werte übernehmen</translation>
        </message>
        <message>
            <source>&amp;History…</source>
            <translation>Verlau&amp;f…</translation>
        </message>
        <message>
            <source>Every operation recorded on a valve's parameters</source>
            <translation>Jeder aufgezeichnete Vorgang an den Parametern eines Ventils</translation>
        </message>
    </context>
    <context>
        <name>MainStatusBar</name>
        <message>
            <source>ONLINE</source>
            <translation>ONLINE</translation>
        </message>
        <message>
            <source>OFFLINE</source>
            <translation>OFFLINE</translation>
        </message>
        <message>
            <source>CONNECTING</source>
            <translation>VERBINDEN</translation>
        </message>
        <message>
            <source>Mode: {0}</source>
            <translation>Modus: {0}</translation>
        </message>
        <message>
            <source>Connected, but the document and the valve do not agree yet: edits are not sent to the valve</source>
            <translation>Verbunden, aber Dokument und Ventil stimmen noch nicht überein: Änderungen werden nicht an das Ventil gesendet</translation>
        </message>
        <message>
            <source>RECONNECTING… {0} s</source>
            <translation>NEU VERBINDEN… {0} s</translation>
        </message>
        <message>
            <source>The link to the valve {0} broke. prm9tool looks for it and compares when it is back; nothing is written to the valve without you.</source>
            <translation>Die Verbindung zum Ventil {0} ist abgebrochen. prm9tool sucht es und vergleicht, sobald es wieder da ist; ohne Sie wird nichts ins Ventil geschrieben.</translation>
        </message>
        <message>
            <source>Expert</source>
            <translation>Experte</translation>
        </message>
        <message>
            <source>Basic</source>
            <translation>Basis</translation>
        </message>
        <message>
            <source>Level: {0}</source>
            <translation>Stufe: {0}</translation>
        </message>
        <message>
            <source>Status: {0}</source>
            <translation>Status: {0}</translation>
        </message>
        <message>
            <source>FW: {0}</source>
            <translation>FW: {0}</translation>
        </message>
        <message>
            <source>untitled</source>
            <translation>unbenannt</translation>
        </message>
        <message numerus="yes">
            <source>%n sample(s) lost</source>
            <translation>
                <numerusform>%n Messwert verloren</numerusform>
                <numerusform>%n Messwerte verloren</numerusform>
            </translation>
        </message>
        <message>
            <source>The oscilloscope stream lost samples: the USB link or the computer could not keep up. The curves have gaps there.</source>
            <translation>Dem Oszilloskop sind Messwerte verloren gegangen: Die USB-Verbindung oder der Computer kam nicht nach. Die Kurven haben dort Lücken.</translation>
        </message>
    </context>
    <context>
        <name>MainWindow</name>
        <message>
            <source>The oscilloscope records in the background: the valve sends three measuring points at a time, so the diagram's other points show — until the recording stops.</source>
            <translation>Das Oszilloskop zeichnet im Hintergrund auf: das Ventil sendet drei Messpunkte gleichzeitig, daher zeigen die übrigen Messpunkte des Diagramms — bis die Aufzeichnung endet.</translation>
        </message>
        <message>
            <source>The oscilloscope works in online mode only.</source>
            <translation>Das Oszilloskop arbeitet nur im Online-Modus.</translation>
        </message>
        <message>
            <source>untitled</source>
            <translation>unbenannt</translation>
        </message>
        <message>
            <source>prm9tool</source>
            <translation>prm9tool</translation>
        </message>
        <message>
            <source>Parameterization of PRM9 proportional directional valves.</source>
            <translation>Parametrierung von PRM9-Proportional-Wegeventilen.</translation>
        </message>
        <message>
            <source>Free software under the GNU General Public License v3 or later.</source>
            <translation>Freie Software unter der GNU General Public License v3 oder später.</translation>
        </message>
        <message>
            <source>About prm9tool</source>
            <translation>Über prm9tool</translation>
        </message>
    </context>
    <context>
        <name>ObjectDictionaryDialog</name>
        <message>
            <source>Object dictionary</source>
            <translation>Objektverzeichnis</translation>
        </message>
        <message>
            <source>Index</source>
            <translation>Index</translation>
        </message>
        <message>
            <source>Sub</source>
            <translation>Sub</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>Name</translation>
        </message>
        <message>
            <source>Type</source>
            <translation>Typ</translation>
        </message>
        <message>
            <source>Access</source>
            <translation>Zugriff</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Wert</translation>
        </message>
        <message>
            <source>Search: index, name, type or value</source>
            <translation>Suchen: Index, Name, Typ oder Wert</translation>
        </message>
        <message>
            <source>Read all</source>
            <translation>Alle lesen</translation>
        </message>
        <message>
            <source>Double-click a writable object to write it.</source>
            <translation>Ein beschreibbares Objekt doppelklicken, um es zu schreiben.</translation>
        </message>
        <message>
            <source>Reading only: writing needs the Expert level.</source>
            <translation>Nur lesen: Schreiben erfordert die Expertenstufe.</translation>
        </message>
        <message>
            <source>— (no entry)</source>
            <translation>— (kein Eintrag)</translation>
        </message>
        <message>
            <source>Write {0}</source>
            <translation>{0} schreiben</translation>
        </message>
        <message>
            <source>{0} ({1}), raw value:</source>
            <translation>{0} ({1}), Rohwert:</translation>
        </message>
    </context>
    <context>
        <name>OnlineDiffDialog</name>
        <message>
            <source>Document and valve differ</source>
            <translation>Dokument und Ventil unterscheiden sich</translation>
        </message>
        <message>
            <source>Take the valve's values</source>
            <translation>Werte des Ventils übernehmen</translation>
        </message>
        <message>
            <source>Send the document's values</source>
            <translation>Werte des Dokuments senden</translation>
        </message>
        <message>
            <source>The document is for another valve variant; it cannot be sent.</source>
            <translation>Das Dokument gehört zu einer anderen Ventilvariante; es kann nicht gesendet werden.</translation>
        </message>
        <message numerus="yes">
            <source>%n value(s) in the document differ from the valve.</source>
            <translation>
                <numerusform>%n Wert im Dokument weicht vom Ventil ab.</numerusform>
                <numerusform>%n Werte im Dokument weichen vom Ventil ab.</numerusform>
            </translation>
        </message>
        <message>
            <source>Document type key: {0} — valve type key: {1}</source>
            <translation>Typschlüssel des Dokuments: {0} – Typschlüssel des Ventils: {1}</translation>
        </message>
        <message>
            <source>The valve is of another variant: only its values can be taken.</source>
            <translation>Das Ventil ist eine andere Variante: Nur seine Werte können übernommen werden.</translation>
        </message>
        <message>
            <source>Cancel stays offline; the document is not changed and nothing is written.</source>
            <translation>Abbrechen bleibt offline; das Dokument bleibt unverändert und nichts wird geschrieben.</translation>
        </message>
        <message>
            <source>Mnemonic</source>
            <translation>Kürzel</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Beschreibung</translation>
        </message>
        <message>
            <source>Document</source>
            <translation>Dokument</translation>
        </message>
        <message>
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
        <message>
            <source>Choose per parameter…</source>
            <translation>Je Parameter wählen…</translation>
        </message>
    </context>
    <context>
        <name>OperationProgress</name>
        <message>
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
    </context>
    <context>
        <name>PagedPrint</name>
        <message>
            <source>Page {0} of {1}</source>
            <translation>Seite {0} von {1}</translation>
        </message>
    </context>
    <context>
        <name>ParameterEditDialog</name>
        <message>
            <source>Parameter {0}</source>
            <translation>Parameter {0}</translation>
        </message>
        <message>
            <source>Current value:</source>
            <translation>Aktueller Wert:</translation>
        </message>
        <message>
            <source>Allowed range:</source>
            <translation>Zulässiger Bereich:</translation>
        </message>
        <message>
            <source>Factory default:</source>
            <translation>Werkseinstellung:</translation>
        </message>
        <message>
            <source>New value:</source>
            <translation>Neuer Wert:</translation>
        </message>
        <message>
            <source>At Basic access level all ramps are set together: {0}.</source>
            <translation>In der Basisstufe werden alle Rampen gemeinsam eingestellt: {0}.</translation>
        </message>
        <message>
            <source>Read-only value of the valve.</source>
            <translation>Nur lesbarer Wert des Ventils.</translation>
        </message>
        <message>
            <source>Can only be changed at Expert access level.</source>
            <translation>Nur in der Expertenstufe änderbar.</translation>
        </message>
        <message>
            <source>{0}: “{1}” is not a number.</source>
            <translation>{0}: „{1}“ ist keine Zahl.</translation>
        </message>
        <message>
            <source>{0}: {1}{2} is outside the allowed range {3}{2}.</source>
            <translation>{0}: {1}{2} liegt außerhalb des zulässigen Bereichs {3}{2}.</translation>
        </message>
    </context>
    <context>
        <name>ParameterListView</name>
        <message>
            <source>Search mnemonic or description…</source>
            <translation>Kürzel oder Beschreibung suchen…</translation>
        </message>
        <message>
            <source>Modified only</source>
            <translation>Nur geänderte</translation>
        </message>
        <message>
            <source>Show only the values that differ from the factory defaults</source>
            <translation>Nur Werte anzeigen, die von der Werkseinstellung abweichen</translation>
        </message>
    </context>
    <context>
        <name>ParameterTableModel</name>
        <message>
            <source>Mnemonic</source>
            <translation>Kürzel</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Beschreibung</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Wert</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>Einheit</translation>
        </message>
        <message>
            <source>Range: {0} … {1} {2}</source>
            <translation>Bereich: {0} … {1} {2}</translation>
        </message>
        <message>
            <source>Factory default: {0} {1}</source>
            <translation>Werkseinstellung: {0} {1}</translation>
        </message>
        <message>
            <source>Read-only value of the valve.</source>
            <translation>Nur lesbarer Wert des Ventils.</translation>
        </message>
        <message>
            <source>Can only be changed at Expert access level.</source>
            <translation>Nur in der Expertenstufe änderbar.</translation>
        </message>
    </context>
    <context>
        <name>PasswordDialog</name>
        <message>
            <source>Expert access level</source>
            <translation>Expertenstufe</translation>
        </message>
        <message>
            <source>The Expert level unlocks the controllers and the linearizations. Changing them needs the appropriate qualification.</source>
            <translation>Die Expertenstufe gibt die Regler und die Linearisierungen frei. Ihre Änderung erfordert die entsprechende Qualifikation.</translation>
        </message>
        <message>
            <source>The password as delivered is written in the help, under “Access levels” (F1, or &lt;a href=&quot;help&quot;&gt;open the help&lt;/a&gt;). A password changed since is known to whoever changed it.</source>
            <translation>Das Passwort im Auslieferungszustand steht in der Hilfe unter „Berechtigungsstufen“ (F1 oder &lt;a href=&quot;help&quot;&gt;Hilfe öffnen&lt;/a&gt;). Ein seither geändertes Passwort kennt, wer es geändert hat.</translation>
        </message>
        <message>
            <source>Password:</source>
            <translation>Passwort:</translation>
        </message>
        <message>
            <source>Wrong password.</source>
            <translation>Falsches Passwort.</translation>
        </message>
    </context>
    <context>
        <name>Problems</name>
        <message>
            <source>{0} two coils{1}</source>
            <translation>{0} zwei Spulen{1}</translation>
        </message>
        <message>
            <source>{0} coil A{1}</source>
            <translation>{0} Spule A{1}</translation>
        </message>
        <message>
            <source>{0} coil B{1}</source>
            <translation>{0} Spule B{1}</translation>
        </message>
        <message>
            <source>{0}: 'value over CANopen' needs a -CA valve</source>
            <translation>{0}: „Wert über CANopen“ erfordert ein Ventil mit -CA</translation>
        </message>
        <message>
            <source>AINSETP: {0} is not a recommended setpoint type for {1} valves (manual table 8-4)</source>
            <translation>AINSETP: {0} ist kein empfohlener Sollwertsignaltyp für Ventile {1} (Handbuch, Tabelle 8-4)</translation>
        </message>
        <message>
            <source>{0} = {1} mA is above the nominal coil current CURNORM = {2} mA</source>
            <translation>{0} = {1} mA liegt über dem Nennstrom der Spule CURNORM = {2} mA</translation>
        </message>
        <message>
            <source>{0}: {1} equals {2}; X points must differ</source>
            <translation>{0}: {1} ist gleich {2}; die X-Stützpunkte müssen verschieden sein</translation>
        </message>
        <message>
            <source>{0} linearization points must increase strictly: {1} &lt; {2}</source>
            <translation>{0}: Die Stützpunkte der Linearisierung müssen streng steigend sein: {1} &lt; {2}</translation>
        </message>
        <message>
            <source>{0} linearization outputs must not decrease: {1} &lt; {2}</source>
            <translation>{0}: Die Ausgangswerte der Linearisierung dürfen nicht fallen: {1} &lt; {2}</translation>
        </message>
        <message>
            <source>{0}: {1} is not a number</source>
            <translation>{0}: {1} ist keine Zahl</translation>
        </message>
        <message>
            <source>{0}: {1} is far outside the range</source>
            <translation>{0}: {1} liegt weit außerhalb des Bereichs</translation>
        </message>
        <message>
            <source>{0}: {1} is not a number: the decimals follow a point ({2})</source>
            <translation>{0}: {1} ist keine Zahl: die Dezimalstellen folgen einem Punkt ({2})</translation>
        </message>
        <message>
            <source>{0}: expected text, got {1}</source>
            <translation>{0}: Text erwartet, erhalten: {1}</translation>
        </message>
        <message>
            <source>{0}: expected a number, got {1}</source>
            <translation>{0}: Zahl erwartet, erhalten: {1}</translation>
        </message>
        <message>
            <source>{0}: {1} is not one of the allowed codes {2}</source>
            <translation>{0}: {1} ist keiner der zulässigen Codes {2}</translation>
        </message>
        <message>
            <source>{0}: {1}{2} is outside the allowed range {3} … {4}{2}</source>
            <translation>{0}: {1}{2} liegt außerhalb des zulässigen Bereichs {3} … {4}{2}</translation>
        </message>
        <message>
            <source>{0}: no such parameter on a {1} valve</source>
            <translation>{0}: Diesen Parameter gibt es beim Ventil {1} nicht</translation>
        </message>
        <message>
            <source>{0}:{1}: warning: {2}</source>
            <translation>{0}:{1}: Warnung: {2}</translation>
        </message>
        <message>
            <source>expected {0} as the first entry: not a prm9tool parameter file, or its header is damaged</source>
            <translation>{0} als erster Eintrag erwartet: keine Parameterdatei von prm9tool, oder ihr Kopf ist beschädigt</translation>
        </message>
        <message>
            <source>format {0} is unknown; expected {1}</source>
            <translation>Format {0} ist unbekannt; erwartet: {1}</translation>
        </message>
        <message>
            <source>format version {0} is newer than this prm9tool reads ({1}): update prm9tool</source>
            <translation>Formatversion {0} ist neuer als die, die dieses prm9tool liest ({1}): prm9tool aktualisieren</translation>
        </message>
        <message>
            <source>format version {0} does not exist</source>
            <translation>Formatversion {0} gibt es nicht</translation>
        </message>
        <message>
            <source>no 'type_key = ...' entry: the header is incomplete</source>
            <translation>kein Eintrag 'type_key = ...': Der Kopf ist unvollständig</translation>
        </message>
        <message>
            <source>serial {0} must be a whole number {1} … {2}</source>
            <translation>Seriennummer {0} muss eine ganze Zahl {1} … {2} sein</translation>
        </message>
        <message>
            <source>firmware is empty; the line is left out when saving</source>
            <translation>firmware ist leer; die Zeile entfällt beim Speichern</translation>
        </message>
        <message>
            <source>unknown parameter {0}: kept and written back unchanged</source>
            <translation>unbekannter Parameter {0}: bleibt erhalten und wird unverändert zurückgeschrieben</translation>
        </message>
        <message>
            <source>unknown parameter {0}: kept and written back unchanged (did you mean {1}?)</source>
            <translation>unbekannter Parameter {0}: bleibt erhalten und wird unverändert zurückgeschrieben (meinten Sie {1}?)</translation>
        </message>
        <message>
            <source>{0} ({1}) is a read-only value, not a setting a parameter file can hold</source>
            <translation>{0} ({1}) ist ein nur lesbarer Wert, keine Einstellung, die eine Parameterdatei enthalten kann</translation>
        </message>
        <message>
            <source>{0} ({1}) is set online only and does not belong in a parameter file</source>
            <translation>{0} ({1}) wird nur online eingestellt und gehört nicht in eine Parameterdatei</translation>
        </message>
        <message>
            <source>{0} ({1}) does not exist on {2} valves (type key {3}); remove the line or change the type key</source>
            <translation>{0} ({1}) gibt es bei Ventilen {2} nicht (Typschlüssel {3}); die Zeile entfernen oder den Typschlüssel ändern</translation>
        </message>
        <message>
            <source>{0} ({1}) is not a parameter of {2} valves (type key {3}): they have the object but no external sensor input; remove the line or change the type key</source>
            <translation>{0} ({1}) ist kein Parameter von Ventilen {2} (Typschlüssel {3}): sie haben das Objekt, aber keinen Eingang für einen externen Sensor; die Zeile entfernen oder den Typschlüssel ändern</translation>
        </message>
        <message>
            <source>{0}: no value after '='</source>
            <translation>{0}: kein Wert nach '='</translation>
        </message>
        <message>
            <source>{0}: {1}{2} is stored as {3}{2}, the nearest value the valve can hold</source>
            <translation>{0}: {1}{2} wird als {3}{2} gespeichert, der nächste Wert, den das Ventil speichern kann</translation>
        </message>
        <message>
            <source>{0} has no value: the valve it was read from does not have it over CANopen; not uploaded</source>
            <translation>{0} hat keinen Wert: Das Ventil, aus dem er gelesen wurde, hat ihn über CANopen nicht; wird nicht hochgeladen</translation>
        </message>
        <message>
            <source>{0} ({1}) is missing (required for {2} valves)</source>
            <translation>{0} ({1}) fehlt (erforderlich für Ventile {2})</translation>
        </message>
        <message>
            <source>{0}: no value after '='; only a download over CANopen may leave a value out, marked with the comment '{1}'</source>
            <translation>{0}: kein Wert nach '='; nur ein Auslesen über CANopen darf einen Wert auslassen, gekennzeichnet mit dem Kommentar '{1}'</translation>
        </message>
        <message>
            <source>byte 0x{0} is not UTF-8 text: the file is corrupt</source>
            <translation>Byte 0x{0} ist kein UTF-8-Text: Die Datei ist beschädigt</translation>
        </message>
        <message>
            <source>control character U+{0}: binary data, the file is corrupt</source>
            <translation>Steuerzeichen U+{0}: Binärdaten, die Datei ist beschädigt</translation>
        </message>
        <message>
            <source>text after the checksum line, which must be the last line</source>
            <translation>Text nach der Prüfsummenzeile, die die letzte Zeile sein muss</translation>
        </message>
        <message>
            <source>garbled line: expected 'NAME = value', a '#' comment or a blank line</source>
            <translation>unlesbare Zeile: erwartet 'NAME = Wert', einen '#'-Kommentar oder eine Leerzeile</translation>
        </message>
        <message>
            <source>{0} is set twice (first on line {1})</source>
            <translation>{0} ist zweimal gesetzt (zuerst in Zeile {1})</translation>
        </message>
        <message>
            <source>no value for {0}, which every {1} file holds: these are not the values of such a valve</source>
            <translation>kein Wert für {0}, den jede Datei für {1} enthält: das sind nicht die Werte eines solchen Ventils</translation>
        </message>
        <message>
            <source>too large to be a parameter file ({0} bytes, more than {1})</source>
            <translation>zu groß für eine Parameterdatei ({0} Bytes, mehr als {1})</translation>
        </message>
        <message>
            <source>the file is empty</source>
            <translation>die Datei ist leer</translation>
        </message>
        <message>
            <source>no 'checksum = ...' line at the end: the file is truncated (a file written by hand must end with one, e.g. 'checksum = crc32:00000000')</source>
            <translation>keine Zeile 'checksum = ...' am Ende: Die Datei ist abgeschnitten (eine von Hand geschriebene Datei muss mit einer solchen Zeile enden, z. B. 'checksum = crc32:00000000')</translation>
        </message>
        <message>
            <source>checksum {0} is damaged (expected crc32: and 8 hex digits)</source>
            <translation>Prüfsumme {0} ist beschädigt (erwartet: crc32: und 8 Hexadezimalziffern)</translation>
        </message>
        <message>
            <source>checksum does not match: the file was changed outside prm9tool (edited by hand?); saving it from prm9tool writes a new checksum</source>
            <translation>Prüfsumme stimmt nicht: Die Datei wurde außerhalb von prm9tool geändert (von Hand bearbeitet?); Speichern aus prm9tool schreibt eine neue Prüfsumme</translation>
        </message>
        <message>
            <source>cannot read the file: {0}</source>
            <translation>die Datei kann nicht gelesen werden: {0}</translation>
        </message>
        <message>
            <source>cannot save the file: {0}</source>
            <translation>die Datei kann nicht gespeichert werden: {0}</translation>
        </message>
        <message>
            <source>{0}: {1} is ambiguous (a thousands separator?); write the number without one, with '{2}' before the decimals</source>
            <translation>{0}: {1} ist mehrdeutig (ein Tausendertrennzeichen?); schreiben Sie die Zahl ohne Trennzeichen, mit „{2}“ vor den Nachkommastellen</translation>
        </message>
        <message>
            <source>unreadable EEPROM image of an emulated valve: {0}</source>
            <translation>unlesbares EEPROM-Abbild eines emulierten Ventils: {0}</translation>
        </message>
        <message>
            <source>not an emulator EEPROM image (format {0})</source>
            <translation>kein EEPROM-Abbild des Emulators (Format {0})</translation>
        </message>
        <message>
            <source>unsupported EEPROM image version {0}</source>
            <translation>nicht unterstützte Version {0} des EEPROM-Abbilds</translation>
        </message>
        <message>
            <source>the image belongs to a {0} valve, not to {1}: give the emulated valve another serial (TYPEKEY:SERIAL) or delete the file</source>
            <translation>das Abbild gehört zu einem Ventil {0}, nicht zu {1}: Geben Sie dem emulierten Ventil eine andere Seriennummer (TYPSCHLÜSSEL:SERIENNUMMER) oder löschen Sie die Datei</translation>
        </message>
        <message>
            <source>the EEPROM image has no 'values' table</source>
            <translation>das EEPROM-Abbild hat keine Tabelle 'values'</translation>
        </message>
    </context>
    <context>
        <name>RampsDialog</name>
        <message>
            <source>All ramps (for a 100 % step)</source>
            <translation>Alle Rampen (für einen 100-%-Sprung)</translation>
        </message>
        <message>
            <source>the ramps differ</source>
            <translation>die Rampen unterscheiden sich</translation>
        </message>
        <message>
            <source>Basic access level: one time sets all ramps. Expert level sets each ramp on its own.</source>
            <translation>Basisstufe: Eine Zeit stellt alle Rampen ein. Die Expertenstufe stellt jede Rampe einzeln ein.</translation>
        </message>
        <message>
            <source>Each time is for a 100 % step; a 50 % step takes half as long.</source>
            <translation>Jede Zeit gilt für einen 100-%-Sprung; ein 50-%-Sprung dauert halb so lange.</translation>
        </message>
        <message>
            <source>100 % step</source>
            <translation>100-%-Sprung</translation>
        </message>
        <message>
            <source>50 % step</source>
            <translation>50-%-Sprung</translation>
        </message>
        <message>
            <source>Time (ms)</source>
            <translation>Zeit (ms)</translation>
        </message>
        <message>
            <source>Demand value (%)</source>
            <translation>Sollwert (%)</translation>
        </message>
    </context>
    <context>
        <name>Record</name>
        <message>
            <source>serial number {0}</source>
            <translation>Seriennummer {0}</translation>
        </message>
        <message>
            <source>PRM9 parameter record</source>
            <translation>PRM9-Parameterprotokoll</translation>
        </message>
        <message>
            <source>untitled</source>
            <translation>unbenannt</translation>
        </message>
        <message>
            <source>untitled (the values are not saved in a file)</source>
            <translation>unbenannt (die Werte sind in keiner Datei gespeichert)</translation>
        </message>
        <message>
            <source>{0} (changed, not saved: the file holds another valve type)</source>
            <translation>{0} (geändert, nicht gespeichert: Die Datei enthält einen anderen Ventiltyp)</translation>
        </message>
        <message>
            <source>{0} (changed, not saved: the values marked {1} differ from the file)</source>
            <translation>{0} (geändert, nicht gespeichert: Die mit {1} markierten Werte weichen von der Datei ab)</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Typschlüssel</translation>
        </message>
        <message>
            <source>Serial number</source>
            <translation>Seriennummer</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>File</source>
            <translation>Datei</translation>
        </message>
        <message>
            <source>Date</source>
            <translation>Datum</translation>
        </message>
        <message>
            <source>Access level</source>
            <translation>Berechtigungsstufe</translation>
        </message>
        <message>
            <source>Mnemonic</source>
            <translation>Kürzel</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Beschreibung</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Wert</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>Einheit</translation>
        </message>
        <message>
            <source>Date:</source>
            <translation>Datum:</translation>
        </message>
        <message>
            <source>Name:</source>
            <translation>Name:</translation>
        </message>
        <message>
            <source>Signature:</source>
            <translation>Unterschrift:</translation>
        </message>
    </context>
    <context>
        <name>RecordActions</name>
        <message>
            <source>Expert</source>
            <translation>Experte</translation>
        </message>
        <message>
            <source>Basic</source>
            <translation>Basis</translation>
        </message>
        <message>
            <source>Parameter record printed</source>
            <translation>Parameterprotokoll gedruckt</translation>
        </message>
        <message>
            <source>Export PDF</source>
            <translation>PDF exportieren</translation>
        </message>
        <message>
            <source>PDF files (*.pdf)</source>
            <translation>PDF-Dateien (*.pdf)</translation>
        </message>
        <message>
            <source>Cannot write “{0}”: {1}</source>
            <translation>„{0}“ kann nicht geschrieben werden: {1}</translation>
        </message>
        <message>
            <source>Parameter record saved as {0}</source>
            <translation>Parameterprotokoll gespeichert als {0}</translation>
        </message>
        <message>
            <source>PRM9 parameter record {0}</source>
            <translation>PRM9-Parameterprotokoll {0}</translation>
        </message>
    </context>
    <context>
        <name>RecordControls</name>
        <message>
            <source>Record…</source>
            <translation>Aufzeichnen…</translation>
        </message>
        <message>
            <source>Record every frame of the CAN bus into a trace file</source>
            <translation>Jeden Frame des CAN-Busses in eine Trace-Datei aufzeichnen</translation>
        </message>
        <message>
            <source>Stop recording</source>
            <translation>Aufzeichnung beenden</translation>
        </message>
        <message>
            <source>Opening the CAN bus…</source>
            <translation>CAN-Bus wird geöffnet…</translation>
        </message>
        <message>
            <source>Record the CAN bus</source>
            <translation>CAN-Bus aufzeichnen</translation>
        </message>
        <message>
            <source>CAN traces ({0})</source>
            <translation>CAN-Traces ({0})</translation>
        </message>
        <message>
            <source>Recording into {0}: {1} frames</source>
            <translation>Aufzeichnung in {0}: {1} Frames</translation>
        </message>
        <message>
            <source>{0} frames recorded into {1}</source>
            <translation>{0} Frames in {1} aufgezeichnet</translation>
        </message>
        <message>
            <source>Not recording: {0}</source>
            <translation>Keine Aufzeichnung: {0}</translation>
        </message>
    </context>
    <context>
        <name>RecordDetailsDialog</name>
        <message>
            <source>History record {0} of valve {1}</source>
            <translation>Verlaufseintrag {0} des Ventils {1}</translation>
        </message>
        <message>
            <source>What was done</source>
            <translation>Was getan wurde</translation>
        </message>
        <message>
            <source>Outcome</source>
            <translation>Ergebnis</translation>
        </message>
        <message>
            <source>Time (UTC)</source>
            <translation>Zeit (UTC)</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Typenschlüssel</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>User, station, link</source>
            <translation>Benutzer, Station, Verbindung</translation>
        </message>
        <message>
            <source>Failed figures:</source>
            <translation>Nicht bestandene Kennwerte:</translation>
        </message>
        <message>
            <source>Open the PDF</source>
            <translation>PDF öffnen</translation>
        </message>
        <message>
            <source>Compare with the record before</source>
            <translation>Mit dem Eintrag davor vergleichen</translation>
        </message>
        <message>
            <source>Details:</source>
            <translation>Details:</translation>
        </message>
        <message>
            <source>The PDF cannot be opened: {0}</source>
            <translation>Das PDF lässt sich nicht öffnen: {0}</translation>
        </message>
    </context>
    <context>
        <name>ReportPage</name>
        <message>
            <source>Acceptance profile</source>
            <translation>Abnahmeprofil</translation>
        </message>
        <message>
            <source>steps of %1 %, a sine sweep of ±%2 % and a triangle over the whole range, about %3 s</source>
            <translation>Sprünge von %1 %, ein Sinus-Sweep von ±%2 % und ein Dreieck über den ganzen Bereich, etwa %3 s</translation>
        </message>
        <message>
            <source>Result: %1</source>
            <translation>Ergebnis: %1</translation>
        </message>
        <message>
            <source>Limited by the link: %1</source>
            <translation>Durch die Verbindung begrenzt: %1</translation>
        </message>
        <message>
            <source>Save the test report</source>
            <translation>Prüfbericht speichern</translation>
        </message>
        <message>
            <source>Cannot write the report: %1</source>
            <translation>Der Bericht kann nicht geschrieben werden: %1</translation>
        </message>
        <message>
            <source>Acceptance profile (TOML, empty: default):</source>
            <translation>Abnahmeprofil (TOML, leer: Standard):</translation>
        </message>
        <message>
            <source>Run the end-of-line test</source>
            <translation>Endprüfung starten</translation>
        </message>
        <message>
            <source>Save PDF and CSV…</source>
            <translation>PDF und CSV speichern…</translation>
        </message>
        <message>
            <source>Browse…</source>
            <translation>Durchsuchen…</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>Kennwert</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Wert</translation>
        </message>
        <message>
            <source>Limit</source>
            <translation>Grenze</translation>
        </message>
        <message>
            <source>Result</source>
            <translation>Ergebnis</translation>
        </message>
    </context>
    <context>
        <name>RestartDialog</name>
        <message>
            <source>Restart valve</source>
            <translation>Ventil neu starten</translation>
        </message>
        <message>
            <source>Restore factory values</source>
            <translation>Werkseinstellungen wiederherstellen</translation>
        </message>
        <message>
            <source>Verify by restart</source>
            <translation>Durch Neustart prüfen</translation>
        </message>
        <message>
            <source>Restore and restart</source>
            <translation>Wiederherstellen und neu starten</translation>
        </message>
        <message>
            <source>Restart and verify</source>
            <translation>Neu starten und prüfen</translation>
        </message>
        <message>
            <source>&lt;b&gt;Restarting the valve electronics is only allowed with the hydraulic circuit disconnected.&lt;/b&gt;&lt;br&gt;During the restart the spool returns to its spring-centred position and the setpoint is ignored for a few seconds.</source>
            <translation>&lt;b&gt;Ein Neustart der Ventilelektronik ist nur bei getrenntem Hydraulikkreis erlaubt.&lt;/b&gt;&lt;br&gt;Während des Neustarts kehrt der Schieber in die federzentrierte Mittelstellung zurück und der Sollwert wird einige Sekunden ignoriert.</translation>
        </message>
        <message>
            <source>The valve's stored parameters are reset to the factory values, which take effect after a restart of the valve. Before that, the valve's parameters are saved to a backup file (if this valve has no backup yet).</source>
            <translation>Die gespeicherten Parameter des Ventils werden auf die Werkseinstellungen zurückgesetzt; sie werden nach einem Neustart des Ventils wirksam. Vorher werden die Parameter des Ventils in einer Sicherungsdatei gespeichert (falls es für dieses Ventil noch keine Sicherung gibt).</translation>
        </message>
        <message>
            <source>The hydraulics are disconnected</source>
            <translation>Die Hydraulik ist getrennt</translation>
        </message>
        <message>
            <source>Restart</source>
            <translation>Neu starten</translation>
        </message>
    </context>
    <context>
        <name>RestartVerifier</name>
        <message>
            <source>Verify by restart</source>
            <translation>Durch Neustart prüfen</translation>
        </message>
        <message>
            <source>Upload the parameters to the valve first: the verification restarts the valve and reads back whether it kept the last upload.</source>
            <translation>Laden Sie die Parameter zuerst in das Ventil hoch: Die Prüfung startet das Ventil neu und liest zurück, ob es die zuletzt hochgeladenen Werte behalten hat.</translation>
        </message>
        <message>
            <source>The valve works with values changed online since the upload that it has not stored: a restart would lose them. Store them first (Valve → Store in valve), then verify. The valve was not restarted.</source>
            <translation>Das Ventil arbeitet mit seit dem Hochladen online geänderten Werten, die es nicht gespeichert hat: Ein Neustart würde sie verlieren. Speichern Sie sie zuerst (Ventil → Im Ventil speichern) und prüfen Sie dann. Das Ventil wurde nicht neu gestartet.</translation>
        </message>
        <message numerus="yes">
            <source>The last upload wrote %n parameter(s): {0}. The valve is restarted, then its parameters are read back and compared with the document: this shows that it keeps them through a restart, as after a power loss.</source>
            <translation>
                <numerusform>Das letzte Hochladen schrieb %n Parameter: {0}. Das Ventil wird neu gestartet, dann werden seine Parameter zurückgelesen und mit dem Dokument verglichen: Das zeigt, dass es sie über einen Neustart behält, wie nach einem Stromausfall.</numerusform>
                <numerusform>Das letzte Hochladen schrieb %n Parameter: {0}. Das Ventil wird neu gestartet, dann werden seine Parameter zurückgelesen und mit dem Dokument verglichen: Das zeigt, dass es sie über einen Neustart behält, wie nach einem Stromausfall.</numerusform>
            </translation>
        </message>
        <message>
            <source>Verification by restart cancelled: the valve was not restarted</source>
            <translation>Prüfung durch Neustart abgebrochen: Das Ventil wurde nicht neu gestartet</translation>
        </message>
        <message>
            <source>Restarting the valve and reading its parameters back…</source>
            <translation>Das Ventil wird neu gestartet und seine Parameter werden zurückgelesen…</translation>
        </message>
        <message>
            <source>stored with its store command</source>
            <translation>mit seinem Speicherbefehl gespeichert</translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) of the last upload read back unchanged at {0}: {1}</source>
            <translation>
                <numerusform>%n Parameter des letzten Hochladens um {0} unverändert zurückgelesen: {1}</numerusform>
                <numerusform>%n Parameter des letzten Hochladens um {0} unverändert zurückgelesen: {1}</numerusform>
            </translation>
        </message>
        <message>
            <source>Verification by restart failed: the valve did not keep {0}</source>
            <translation>Prüfung durch Neustart fehlgeschlagen: Das Ventil hat {0} nicht behalten</translation>
        </message>
        <message numerus="yes">
            <source>After the restart the valve reads back %n value(s) of the last upload otherwise: it did not keep them ({0}). It works with the values read back now (expected → read back below); the document still holds the uploaded values and the history records the differences. Edits no longer go to the valve: upload the document again, or download the valve's values.</source>
            <translation>
                <numerusform>Nach dem Neustart liest das Ventil %n Wert des letzten Hochladens anders zurück: Es hat ihn nicht behalten ({0}). Es arbeitet mit dem jetzt zurückgelesenen Wert (erwartet → zurückgelesen unten); das Dokument enthält weiterhin den hochgeladenen Wert, und der Verlauf zeichnet die Abweichung auf. Änderungen gehen nicht mehr an das Ventil: Laden Sie das Dokument erneut hoch oder laden Sie die Werte des Ventils herunter.</numerusform>
                <numerusform>Nach dem Neustart liest das Ventil %n Werte des letzten Hochladens anders zurück: Es hat sie nicht behalten ({0}). Es arbeitet mit den jetzt zurückgelesenen Werten (erwartet → zurückgelesen unten); das Dokument enthält weiterhin die hochgeladenen Werte, und der Verlauf zeichnet die Abweichungen auf. Änderungen gehen nicht mehr an das Ventil: Laden Sie das Dokument erneut hoch oder laden Sie die Werte des Ventils herunter.</numerusform>
            </translation>
        </message>
        <message>
            <source>The valve did not come back after the restart</source>
            <translation>Das Ventil hat sich nach dem Neustart nicht wieder gemeldet</translation>
        </message>
        <message>
            <source>Check the valve's supply and cable, then go online again: prm9tool compares the valve with the document.</source>
            <translation>Prüfen Sie Versorgung und Kabel des Ventils und gehen Sie dann wieder online: prm9tool vergleicht das Ventil mit dem Dokument.</translation>
        </message>
        <message>
            <source>prm9tool looks for the valve; when it is back, prm9tool compares it with the document and you decide what to do.</source>
            <translation>prm9tool sucht das Ventil; wenn es wieder da ist, vergleicht prm9tool es mit dem Dokument, und Sie entscheiden, was geschieht.</translation>
        </message>
        <message>
            <source>The valve did not come back after the restart; prm9tool is offline now.
As far as known, the valve holds the values of the last upload ({0}): every one read back correctly before the restart, but whether it kept them through the restart could not be read.
Nothing was lost on the PC side: the document still holds every value, the backup and the history are unchanged. {1}</source>
            <translation>Das Ventil hat sich nach dem Neustart nicht wieder gemeldet; prm9tool ist jetzt offline.
Soweit bekannt, hält das Ventil die zuletzt hochgeladenen Werte ({0}): Jeder wurde vor dem Neustart richtig zurückgelesen, ob es sie über den Neustart behalten hat, ließ sich aber nicht lesen.
Auf dem PC ging nichts verloren: Das Dokument enthält weiterhin jeden Wert, Sicherung und Verlauf sind unverändert. {1}</translation>
        </message>
    </context>
    <context>
        <name>ScopeDisplay</name>
        <message>
            <source>the samples between cursors A and B</source>
            <translation>die Abtastwerte zwischen Cursor A und B</translation>
        </message>
        <message>
            <source>the visible window</source>
            <translation>das sichtbare Fenster</translation>
        </message>
    </context>
    <context>
        <name>ScopeExport</name>
        <message>
            <source>Nothing recorded yet.</source>
            <translation>Noch nichts aufgezeichnet.</translation>
        </message>
        <message>
            <source>Could not write {0}.</source>
            <translation>{0} konnte nicht geschrieben werden.</translation>
        </message>
        <message>
            <source>Export CSV</source>
            <translation>CSV exportieren</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>CSV-Dateien (*.csv)</translation>
        </message>
        <message>
            <source>Export PNG</source>
            <translation>PNG exportieren</translation>
        </message>
        <message>
            <source>PNG images (*.png)</source>
            <translation>PNG-Bilder (*.png)</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>Export</translation>
        </message>
        <message>
            <source>Saved {0}.</source>
            <translation>{0} gespeichert.</translation>
        </message>
    </context>
    <context>
        <name>ScopePlot</name>
        <message>
            <source>Auto</source>
            <translation>Auto</translation>
        </message>
        <message>
            <source>Scale this channel to its data again</source>
            <translation>Diesen Kanal wieder an seine Daten anpassen</translation>
        </message>
        <message>
            <source>at stop:</source>
            <translation>bei Stopp:</translation>
        </message>
        <message>
            <source>The last value recorded before Stop; the valve may hold another now.</source>
            <translation>Der letzte vor „Stopp“ aufgezeichnete Wert; das Ventil kann inzwischen einen anderen haben.</translation>
        </message>
        <message>
            <source>Time from trigger [ms]</source>
            <translation>Zeit ab Trigger [ms]</translation>
        </message>
        <message>
            <source>Time from trigger [s]</source>
            <translation>Zeit ab Trigger [s]</translation>
        </message>
        <message>
            <source>Time [ms]</source>
            <translation>Zeit [ms]</translation>
        </message>
        <message>
            <source>Time [s]</source>
            <translation>Zeit [s]</translation>
        </message>
        <message>
            <source>The valve's newest value. The plot holds an earlier recording; read it with the cursors.</source>
            <translation>Der neueste Wert des Ventils. Das Diagramm hält eine frühere Aufzeichnung; lesen Sie sie mit den Cursorn ab.</translation>
        </message>
        <message>
            <source>live:</source>
            <translation>live:</translation>
        </message>
    </context>
    <context>
        <name>ScopeStatusText</name>
        <message>
            <source>The valve does not follow its setpoint: {0}</source>
            <translation>Das Ventil folgt seinem Sollwert nicht: {0}</translation>
        </message>
        <message>
            <source>Stopped. Choose up to three measuring points and press Start.</source>
            <translation>Gestoppt. Wählen Sie bis zu drei Messpunkte und drücken Sie Start.</translation>
        </message>
        <message>
            <source>Single capture complete. Resume arms the trigger again.</source>
            <translation>Einzelaufnahme abgeschlossen. Fortsetzen schärft den Trigger erneut.</translation>
        </message>
        <message>
            <source>Paused: zoom and pan with the mouse; recording continues.</source>
            <translation>Pausiert: mit der Maus zoomen und verschieben; die Aufzeichnung läuft weiter.</translation>
        </message>
        <message>
            <source>Waiting for the trigger…</source>
            <translation>Warten auf den Trigger…</translation>
        </message>
        <message>
            <source>Recording at {0} Hz.</source>
            <translation>Aufzeichnung mit {0} Hz.</translation>
        </message>
        <message>
            <source>Recording at {0} Hz of the {1} Hz asked for: {2} samples lost on the link.</source>
            <translation>Aufzeichnung mit {0} Hz der angeforderten {1} Hz: {2} Abtastwerte auf der Verbindung verloren.</translation>
        </message>
        <message>
            <source>The oscilloscope needs a connected valve: go online (Communication → Online).</source>
            <translation>Das Oszilloskop braucht ein verbundenes Ventil: wechseln Sie online (Kommunikation → Online).</translation>
        </message>
        <message>
            <source>The recording stopped: another operation (a tuning test…) took the stream.</source>
            <translation>Die Aufzeichnung wurde beendet: Ein anderer Vorgang (ein Einstell- oder Prüftest…) hat den Datenstrom übernommen.</translation>
        </message>
        <message>
            <source>The recording stopped: {0}</source>
            <translation>Die Aufzeichnung wurde beendet: {0}</translation>
        </message>
        <message>
            <source>The link dropped: the setpoint generator has stopped.</source>
            <translation>Die Verbindung ist abgebrochen: Der Sollwertgenerator wurde gestoppt.</translation>
        </message>
        <message>
            <source>The setpoint generator has stopped: another operation (a tuning test, an upload…) drives the valve now.</source>
            <translation>Der Sollwertgenerator wurde gestoppt: Ein anderer Vorgang (ein Einstell- oder Prüftest, das Hochladen in das Ventil…) steuert jetzt das Ventil.</translation>
        </message>
        <message>
            <source>The valve refused a value of the setpoint generator ({0}): the generator has stopped.</source>
            <translation>Das Ventil hat einen Wert des Sollwertgenerators abgelehnt ({0}): Der Generator wurde gestoppt.</translation>
        </message>
        <message>
            <source>no reason given</source>
            <translation>ohne Angabe eines Grundes</translation>
        </message>
    </context>
    <context>
        <name>ScopeWidget</name>
        <message>
            <source>Select at least one measuring point on the right.</source>
            <translation>Wählen Sie rechts mindestens einen Messpunkt.</translation>
        </message>
        <message>
            <source>The recording could not start: {0}</source>
            <translation>Die Aufzeichnung konnte nicht starten: {0}</translation>
        </message>
        <message>
            <source>Tuning and characterization…</source>
            <translation>Einstellung und Charakterisierung…</translation>
        </message>
    </context>
    <context>
        <name>SensorScalingDialog</name>
        <message>
            <source>Sensor signal in (%)</source>
            <translation>Sensorsignal ein (%)</translation>
        </message>
        <message>
            <source>Process actual value (%)</source>
            <translation>Prozessistwert (%)</translation>
        </message>
        <message>
            <source>1:1</source>
            <translation>1:1</translation>
        </message>
        <message>
            <source>after offset and gain</source>
            <translation>nach Offset und Verstärkung</translation>
        </message>
    </context>
    <context>
        <name>Service</name>
        <message>
            <source>the setpoint generator</source>
            <translation>der Sollwertgenerator</translation>
        </message>
        <message>
            <source>the capture with a stimulus</source>
            <translation>die Aufzeichnung mit Anregung</translation>
        </message>
        <message>
            <source>the tuning test</source>
            <translation>der Einstelltest</translation>
        </message>
        <message>
            <source>the characterization</source>
            <translation>die Charakterisierung</translation>
        </message>
        <message>
            <source>the autotune</source>
            <translation>das Autotune</translation>
        </message>
        <message>
            <source>the field signature</source>
            <translation>die Feldsignatur</translation>
        </message>
        <message>
            <source>{0} cannot start while {1} runs on this valve: stop {1} first; nothing was started</source>
            <translation>{0} kann nicht starten, solange {1} an diesem Ventil läuft: zuerst {1} beenden; nichts wurde gestartet</translation>
        </message>
        <message>
            <source>{0}: expected a number in {1}, got {2}</source>
            <translation>{0}: erwartet eine Zahl in {1}, nicht {2}</translation>
        </message>
        <message>
            <source>{0}: the parameter is read-only</source>
            <translation>{0}: der Parameter ist schreibgeschützt</translation>
        </message>
    </context>
    <context>
        <name>SetpointGenerator</name>
        <message>
            <source>The setpoint generator needs a connected valve.</source>
            <translation>Der Sollwertgenerator braucht ein verbundenes Ventil.</translation>
        </message>
        <message>
            <source>The valve is busy with another operation; start the generator after it.</source>
            <translation>Das Ventil ist mit einem anderen Vorgang beschäftigt; starten Sie den Generator danach.</translation>
        </message>
    </context>
    <context>
        <name>SignalInputDialog</name>
        <message>
            <source>%1 — recommended</source>
            <translation>%1 – empfohlen</translation>
        </message>
        <message>
            <source>Recommended for this coil layout (manual table 8-4) are the types marked 'recommended'. With positive polarity a positive setpoint drives coil A.</source>
            <translation>Für diese Spulenanordnung empfohlen (Anleitung Tabelle 8-4) sind die mit „empfohlen“ gekennzeichneten Typen. Bei positiver Polarität steuert ein positiver Sollwert Spule A an.</translation>
        </message>
        <message>
            <source>With inverted polarity the sensor signal enters the process loop with a negative sign.</source>
            <translation>Bei invertierter Polarität geht das Sensorsignal mit negativem Vorzeichen in den Prozessregelkreis ein.</translation>
        </message>
        <message>
            <source>Input signal (%1)</source>
            <translation>Eingangssignal (%1)</translation>
        </message>
        <message>
            <source>Internal value (%)</source>
            <translation>Interner Wert (%)</translation>
        </message>
        <message>
            <source>internal value</source>
            <translation>interner Wert</translation>
        </message>
        <message>
            <source>This type is not recommended for a valve with %1 (manual table 8-4).</source>
            <translation>Dieser Typ wird für ein Ventil mit %1 nicht empfohlen (Anleitung Tabelle 8-4).</translation>
        </message>
    </context>
    <context>
        <name>SignaturePage</name>
        <message>
            <source>The birth certificate is compared with the valve itself: go online with the valve first.</source>
            <translation>Die Geburtsurkunde wird mit dem Ventil selbst verglichen: Gehen Sie zuerst mit dem Ventil online.</translation>
        </message>
        <message>
            <source>a small and a large step each way, a short sine sweep and a hysteresis loop, at most %1 s</source>
            <translation>ein kleiner und ein großer Sprung in jede Richtung, ein kurzer Sinus-Sweep und eine Hystereseschleife, höchstens %1 s</translation>
        </message>
        <message>
            <source>Not compared: %1</source>
            <translation>Nicht verglichen: %1</translation>
        </message>
        <message>
            <source>Save the drift report</source>
            <translation>Driftbericht speichern</translation>
        </message>
        <message>
            <source>Cannot write the report: %1</source>
            <translation>Der Bericht kann nicht geschrieben werden: %1</translation>
        </message>
        <message>
            <source>A short field signature of the valve, compared with its birth certificate: the end-of-line test kept in the history for its serial. Each figure is judged against the drift limits of the acceptance profile chosen on the Test report page ([drift]; empty: the defaults).</source>
            <translation>Eine kurze Feldsignatur des Ventils, verglichen mit seiner Geburtsurkunde: der Endprüfung, die der Verlauf zu seiner Seriennummer aufbewahrt. Jeder Kennwert wird an den Driftgrenzen des auf der Seite Prüfbericht gewählten Abnahmeprofils gemessen ([drift]; leer: die Vorgaben).</translation>
        </message>
        <message>
            <source>Compare with birth certificate</source>
            <translation>Mit Geburtsurkunde vergleichen</translation>
        </message>
        <message>
            <source>Save PDF…</source>
            <translation>PDF speichern…</translation>
        </message>
    </context>
    <context>
        <name>SignatureReport</name>
        <message>
            <source>not reached</source>
            <translation>nicht erreicht</translation>
        </message>
        <message>
            <source>above %1</source>
            <translation>über %1</translation>
        </message>
        <message>
            <source>pp</source>
            <translation>Pp</translation>
        </message>
        <message>
            <source>not judged</source>
            <translation>nicht bewertet</translation>
        </message>
        <message>
            <source>DRIFTED</source>
            <translation>DRIFT</translation>
        </message>
        <message>
            <source>within</source>
            <translation>innerhalb</translation>
        </message>
        <message>
            <source>the end-of-line test on %1</source>
            <translation>der Endprüfung am %1</translation>
        </message>
        <message>
            <source>the first characterization on %1</source>
            <translation>der ersten Charakterisierung am %1</translation>
        </message>
        <message>
            <source>No figure drifted beyond its limit since %1.</source>
            <translation>Kein Kennwert ist seit %1 über seine Grenze hinaus gedriftet.</translation>
        </message>
        <message>
            <source>%1 %2, was %3</source>
            <translation>%1 %2, war %3</translation>
        </message>
        <message>
            <source>Drifted since %1: %2.</source>
            <translation>Gedriftet seit %1: %2.</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>Kennwert</translation>
        </message>
        <message>
            <source>Today</source>
            <translation>Heute</translation>
        </message>
        <message>
            <source>Birth certificate</source>
            <translation>Geburtsurkunde</translation>
        </message>
        <message>
            <source>Change</source>
            <translation>Änderung</translation>
        </message>
        <message>
            <source>Drift limit</source>
            <translation>Driftgrenze</translation>
        </message>
        <message>
            <source>Result</source>
            <translation>Ergebnis</translation>
        </message>
        <message>
            <source>birth certificate</source>
            <translation>Geburtsurkunde</translation>
        </message>
        <message>
            <source>today, step down ×−1</source>
            <translation>heute, Sprung abwärts ×−1</translation>
        </message>
        <message>
            <source>setpoint</source>
            <translation>Sollwert</translation>
        </message>
        <message>
            <source>today</source>
            <translation>heute</translation>
        </message>
        <message>
            <source>Step response ±%1 %</source>
            <translation>Sprungantwort ±%1 %</translation>
        </message>
        <message>
            <source>time [ms]</source>
            <translation>Zeit [ms]</translation>
        </message>
        <message>
            <source>frequency [Hz]</source>
            <translation>Frequenz [Hz]</translation>
        </message>
        <message>
            <source>Frequency response: magnitude</source>
            <translation>Frequenzgang: Betrag</translation>
        </message>
        <message>
            <source>Frequency response: phase</source>
            <translation>Frequenzgang: Phase</translation>
        </message>
        <message>
            <source>The birth certificate's record keeps its figures but not its curves (recorded by an older prm9tool): the plots show today's only.</source>
            <translation>Der Eintrag der Geburtsurkunde enthält ihre Kennwerte, aber nicht ihre Kurven (von einem älteren prm9tool aufgezeichnet): Die Diagramme zeigen nur die heutigen.</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Typschlüssel</translation>
        </message>
        <message>
            <source>Serial number</source>
            <translation>Seriennummer</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>Date</source>
            <translation>Datum</translation>
        </message>
        <message>
            <source>Link</source>
            <translation>Verbindung</translation>
        </message>
        <message>
            <source>Loop tested</source>
            <translation>Geprüfter Regelkreis</translation>
        </message>
        <message>
            <source>Drift limits</source>
            <translation>Driftgrenzen</translation>
        </message>
        <message>
            <source>Motion</source>
            <translation>Bewegung</translation>
        </message>
        <message>
            <source>no drift</source>
            <translation>keine Drift</translation>
        </message>
        <message>
            <source>Limited by the link</source>
            <translation>Durch die Verbindung begrenzt</translation>
        </message>
        <message>
            <source>PRM9 field signature and drift report</source>
            <translation>PRM9-Feldsignatur und Driftbericht</translation>
        </message>
        <message>
            <source>{0} · serial number {1}</source>
            <translation>{0} · Seriennummer {1}</translation>
        </message>
        <message>
            <source>PRM9 drift report</source>
            <translation>PRM9-Driftbericht</translation>
        </message>
    </context>
    <context>
        <name>StaticPage</name>
        <message>
            <source>a triangle over the whole range −100 … 100 %, %1 s</source>
            <translation>ein Dreieck über den ganzen Bereich −100 … 100 %, %1 s</translation>
        </message>
        <message>
            <source>Gain %1, hysteresis %2 %, linearity error %3 %, dead band %4 %.</source>
            <translation>Verstärkung %1, Hysterese %2 %, Linearitätsfehler %3 %, Totzone %4 %.</translation>
        </message>
        <message>
            <source>Triangle period:</source>
            <translation>Periode des Dreiecks:</translation>
        </message>
        <message>
            <source>Measure the static characteristic</source>
            <translation>Statische Kennlinie messen</translation>
        </message>
        <message>
            <source>No proposal: this link does not sample the setpoint chain (USB and the emulator do).</source>
            <translation>Kein Vorschlag: Diese Verbindung tastet die Sollwertkette nicht ab (USB und der Emulator tun es).</translation>
        </message>
        <message>
            <source>Dead band behind the gain/offset stage %1 … %2 %: offsets %3.</source>
            <translation>Totband hinter der Verstärkungs-/Offsetstufe %1 … %2 %: Offsets %3.</translation>
        </message>
        <message>
            <source>with the proposed offsets and linearization (preview)</source>
            <translation>mit den vorgeschlagenen Offsets und der Linearisierung (Vorschau)</translation>
        </message>
        <message>
            <source>Offsets and linearization from the static characteristic</source>
            <translation>Offsets und Linearisierung aus der statischen Kennlinie</translation>
        </message>
        <message>
            <source>Apply the proposed offsets and linearization</source>
            <translation>Vorgeschlagene Offsets und Linearisierung übernehmen</translation>
        </message>
    </context>
    <context>
        <name>StepFigures</name>
        <message>
            <source>did not settle within ±{0} % of the step: oscillation of {1} at {2} Hz</source>
            <translation>nicht innerhalb ±{0} % des Sprungs eingeschwungen: Schwingung von {1} bei {2} Hz</translation>
        </message>
        <message>
            <source>did not settle within ±{0} % of the step: still moving by {1} at the end</source>
            <translation>nicht innerhalb ±{0} % des Sprungs eingeschwungen: bewegt sich am Ende noch um {1}</translation>
        </message>
        <message>
            <source>Step {0} → {1} %, window {2} … {3} ms</source>
            <translation>Sprung {0} → {1} %, Fenster {2} … {3} ms</translation>
        </message>
        <message>
            <source>not reached: the response ended at {0} of the setpoint {1}</source>
            <translation>nicht erreicht: die Antwort endete bei {0} des Sollwerts {1}</translation>
        </message>
    </context>
    <context>
        <name>StepPanel</name>
        <message>
            <source>Step response</source>
            <translation>Sprungantwort</translation>
        </message>
        <message>
            <source>Only between cursors A and B</source>
            <translation>Nur zwischen Cursor A und B</translation>
        </message>
        <message>
            <source>Reference</source>
            <translation>Referenz</translation>
        </message>
        <message>
            <source>Response</source>
            <translation>Antwort</translation>
        </message>
        <message>
            <source>Step</source>
            <translation>Sprung</translation>
        </message>
        <message>
            <source>Rise time 10–90 %</source>
            <translation>Anstiegszeit 10–90 %</translation>
        </message>
        <message>
            <source>Overshoot</source>
            <translation>Überschwingen</translation>
        </message>
        <message>
            <source>Settling time ±2 %</source>
            <translation>Ausregelzeit ±2 %</translation>
        </message>
        <message>
            <source>Steady-state error</source>
            <translation>Bleibende Regelabweichung</translation>
        </message>
        <message>
            <source>(none: step on the response)</source>
            <translation>(keine: Sprung auf der Antwort)</translation>
        </message>
        <message>
            <source>No step found: the reference channel has no data in {0}. Over CANopen the valve does not report its demand value; the channel shows the setpoint prm9tool sends while its setpoint generator runs. Start the generator, or choose “(none: step on the response)”.</source>
            <translation>Kein Sprung gefunden: Der Referenzkanal hat in {0} keine Daten. Über CANopen meldet das Ventil seinen Sollwert nicht; der Kanal zeigt den Sollwert, den prm9tool sendet, solange sein Sollwertgenerator läuft. Starten Sie den Generator oder wählen Sie „(keine: Sprung auf der Antwort)“.</translation>
        </message>
        <message>
            <source>No step found: the response channel has no data in {0} (the link does not deliver this measuring point, or lost every sample).</source>
            <translation>Kein Sprung gefunden: Der Antwortkanal hat in {0} keine Daten (die Verbindung liefert diesen Messpunkt nicht oder hat jeden Messwert verloren).</translation>
        </message>
        <message>
            <source>No step found in {0}.</source>
            <translation>Kein Sprung in {0} gefunden.</translation>
        </message>
        <message>
            <source>Measured on {0}.</source>
            <translation>Gemessen auf {0}.</translation>
        </message>
        <message>
            <source>No response to the step in {0}: the response stays flat or within its noise.</source>
            <translation>Keine Antwort auf den Sprung in {0}: Die Antwort bleibt flach oder im Rauschen.</translation>
        </message>
        <message>
            <source>Measured on step {0} of {1} in {2}.</source>
            <translation>Gemessen am Sprung {0} von {1} in {2}.</translation>
        </message>
        <message>
            <source>Window too short: in {0} the response has not come to rest yet. Widen the time window or move the cursors apart.</source>
            <translation>Fenster zu kurz: in {0} ist die Antwort noch nicht zur Ruhe gekommen. Vergrößern Sie das Zeitfenster oder ziehen Sie die Cursor auseinander.</translation>
        </message>
    </context>
    <context>
        <name>StepResponse</name>
        <message>
            <source>not reached</source>
            <translation>nicht erreicht</translation>
        </message>
        <message>
            <source>{0}: overshoot {1} %, rise time {2}, settling (±2 %) {3}, remaining error {4} %</source>
            <translation>{0}: Überschwingen {1} %, Anstiegszeit {2}, Einschwingen (±2 %) {3}, bleibende Abweichung {4} %</translation>
        </message>
    </context>
    <context>
        <name>ThresholdGainDialog</name>
        <message>
            <source>Control deviation in (%)</source>
            <translation>Regelabweichung ein (%)</translation>
        </message>
        <message>
            <source>Setpoint in (%)</source>
            <translation>Sollwert ein (%)</translation>
        </message>
        <message>
            <source>Control deviation out (%)</source>
            <translation>Regelabweichung aus (%)</translation>
        </message>
        <message>
            <source>Setpoint out (%)</source>
            <translation>Sollwert aus (%)</translation>
        </message>
        <message>
            <source>1:1</source>
            <translation>1:1</translation>
        </message>
        <message>
            <source>output</source>
            <translation>Ausgang</translation>
        </message>
    </context>
    <context>
        <name>TraceWindow</name>
        <message>
            <source>CAN trace</source>
            <translation>CAN-Trace</translation>
        </message>
        <message>
            <source>Open trace…</source>
            <translation>Trace öffnen…</translation>
        </message>
        <message>
            <source>Open a trace file (ASC, BLF, TRC or candump log).</source>
            <translation>Öffnen Sie eine Trace-Datei (ASC, BLF, TRC oder candump-Log).</translation>
        </message>
        <message>
            <source>Time (s)</source>
            <translation>Zeit (s)</translation>
        </message>
        <message>
            <source>Node</source>
            <translation>Knoten</translation>
        </message>
        <message>
            <source>Kind</source>
            <translation>Art</translation>
        </message>
        <message>
            <source>Decoding {0}…</source>
            <translation>{0} wird dekodiert…</translation>
        </message>
        <message>
            <source>Open a CAN trace</source>
            <translation>CAN-Trace öffnen</translation>
        </message>
        <message>
            <source>CAN traces ({0})</source>
            <translation>CAN-Traces ({0})</translation>
        </message>
        <message>
            <source>The trace cannot be read: {0}</source>
            <translation>Der Trace kann nicht gelesen werden: {0}</translation>
        </message>
        <message>
            <source>{0}: {1} frames, {2} events, {3} not understood, {4} incidents</source>
            <translation>{0}: {1} Frames, {2} Ereignisse, {3} nicht verstanden, {4} Vorfälle</translation>
        </message>
        <message>
            <source>; SYNC period {0:.3f} ms, jitter {1:.1f} µs</source>
            <translation>; SYNC-Periode {0:.3f} ms, Jitter {1:.1f} µs</translation>
        </message>
        <message>
            <source>every node</source>
            <translation>jeder Knoten</translation>
        </message>
        <message>
            <source>the whole bus</source>
            <translation>der ganze Bus</translation>
        </message>
        <message>
            <source>node {0}</source>
            <translation>Knoten {0}</translation>
        </message>
        <message>
            <source>every kind</source>
            <translation>jede Art</translation>
        </message>
        <message>
            <source>node {0}: {1}</source>
            <translation>Knoten {0}: {1}</translation>
        </message>
    </context>
    <context>
        <name>TuningReport</name>
        <message>
            <source>overshoot</source>
            <translation>Überschwingen</translation>
        </message>
        <message>
            <source>rise time (10–90 %)</source>
            <translation>Anstiegszeit (10–90 %)</translation>
        </message>
        <message>
            <source>settling time (±2 %)</source>
            <translation>Ausregelzeit (±2 %)</translation>
        </message>
        <message>
            <source>−3 dB frequency</source>
            <translation>−3-dB-Frequenz</translation>
        </message>
        <message>
            <source>−90° frequency</source>
            <translation>−90°-Frequenz</translation>
        </message>
        <message>
            <source>gain</source>
            <translation>Verstärkung</translation>
        </message>
        <message>
            <source>hysteresis</source>
            <translation>Hysterese</translation>
        </message>
        <message>
            <source>linearity error</source>
            <translation>Linearitätsfehler</translation>
        </message>
        <message>
            <source>dead band</source>
            <translation>Totzone</translation>
        </message>
        <message>
            <source>step %1 → %2 %: %3</source>
            <translation>Sprung %1 → %2 %: %3</translation>
        </message>
        <message>
            <source>step %1 %: %2</source>
            <translation>Sprung %1 %: %2</translation>
        </message>
        <message>
            <source>process controller (E04): process actual value</source>
            <translation>Prozessregler (E04): Prozess-Istwert</translation>
        </message>
        <message>
            <source>position controller: spool position</source>
            <translation>Lageregler: Schieberlage</translation>
        </message>
        <message>
            <source>emulator (stepped faster than real time)</source>
            <translation>Emulator (schneller als Echtzeit gerechnet)</translation>
        </message>
        <message>
            <source>TPDO1 at the tool's SYNC</source>
            <translation>TPDO1 zum SYNC des Programms</translation>
        </message>
        <message>
            <source>SDO polling</source>
            <translation>SDO-Abfrage</translation>
        </message>
        <message>
            <source>CANopen node {0} ({1}), {2}, one sample per {3} ms</source>
            <translation>CANopen-Knoten {0} ({1}), {2}, ein Abtastwert je {3} ms</translation>
        </message>
        <message>
            <source>default (built in)</source>
            <translation>Standard (eingebaut)</translation>
        </message>
        <message>
            <source>PASS</source>
            <translation>BESTANDEN</translation>
        </message>
        <message>
            <source>FAIL</source>
            <translation>NICHT BESTANDEN</translation>
        </message>
        <message>
            <source>not reached</source>
            <translation>nicht erreicht</translation>
        </message>
        <message>
            <source>above {0}</source>
            <translation>über {0}</translation>
        </message>
        <message>
            <source>Step response %1 %</source>
            <translation>Sprungantwort %1 %</translation>
        </message>
        <message>
            <source>time [ms]</source>
            <translation>Zeit [ms]</translation>
        </message>
        <message>
            <source>setpoint</source>
            <translation>Sollwert</translation>
        </message>
        <message>
            <source>actual</source>
            <translation>Istwert</translation>
        </message>
        <message>
            <source>frequency [Hz]</source>
            <translation>Frequenz [Hz]</translation>
        </message>
        <message>
            <source>Frequency response ±%1 %: magnitude</source>
            <translation>Frequenzgang ±%1 %: Betrag</translation>
        </message>
        <message>
            <source>magnitude</source>
            <translation>Betrag</translation>
        </message>
        <message>
            <source>Phase and coherence</source>
            <translation>Phase und Kohärenz</translation>
        </message>
        <message>
            <source>phase</source>
            <translation>Phase</translation>
        </message>
        <message>
            <source>coherence ×100</source>
            <translation>Kohärenz ×100</translation>
        </message>
        <message>
            <source>Static characteristic</source>
            <translation>Statische Kennlinie</translation>
        </message>
        <message>
            <source>demand [%]</source>
            <translation>Sollwert [%]</translation>
        </message>
        <message>
            <source>actual [%]</source>
            <translation>Istwert [%]</translation>
        </message>
        <message>
            <source>rising</source>
            <translation>steigend</translation>
        </message>
        <message>
            <source>falling</source>
            <translation>fallend</translation>
        </message>
        <message>
            <source>best line</source>
            <translation>Ausgleichsgerade</translation>
        </message>
        <message>
            <source>{0} · serial number {1}</source>
            <translation>{0} · Seriennummer {1}</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Typschlüssel</translation>
        </message>
        <message>
            <source>Serial number</source>
            <translation>Seriennummer</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>Date</source>
            <translation>Datum</translation>
        </message>
        <message>
            <source>Link</source>
            <translation>Verbindung</translation>
        </message>
        <message>
            <source>Loop tested</source>
            <translation>Geprüfter Regelkreis</translation>
        </message>
        <message>
            <source>Acceptance profile</source>
            <translation>Abnahmeprofil</translation>
        </message>
        <message>
            <source>Result</source>
            <translation>Ergebnis</translation>
        </message>
        <message>
            <source>Limited by the link</source>
            <translation>Durch die Verbindung begrenzt</translation>
        </message>
        <message>
            <source>Figures</source>
            <translation>Kennwerte</translation>
        </message>
        <message>
            <source>Parameter set</source>
            <translation>Parametersatz</translation>
        </message>
        <message>
            <source>PRM9 test report</source>
            <translation>PRM9-Prüfbericht</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>Kennwert</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Wert</translation>
        </message>
        <message>
            <source>Limit</source>
            <translation>Grenze</translation>
        </message>
        <message>
            <source>flow characteristic: %1</source>
            <translation>Durchflusskennlinie: %1</translation>
        </message>
        <message>
            <source>Flow characteristic</source>
            <translation>Durchflusskennlinie</translation>
        </message>
        <message>
            <source>spool opening [%]</source>
            <translation>Schieberöffnung [%]</translation>
        </message>
        <message>
            <source>actuator velocity [%/s]</source>
            <translation>Geschwindigkeit des Antriebs [%/s]</translation>
        </message>
        <message>
            <source>measured</source>
            <translation>gemessen</translation>
        </message>
    </context>
    <context>
        <name>TuningRunner</name>
        <message>
            <source>The valve is back: what the broken test had changed is restored ({0}) and the setpoint is the valve's own again.</source>
            <translation>Das Ventil ist zurück: was der abgebrochene Test geändert hatte, ist wiederhergestellt ({0}), und der Sollwert ist wieder der des Ventils.</translation>
        </message>
    </context>
    <context>
        <name>TuningWindow</name>
        <message>
            <source>Running: %1</source>
            <translation>Läuft: %1</translation>
        </message>
        <message>
            <source>This test moves the spool (and on E04 the actuator): %1.

Make sure the hydraulics are safe for it. Stop ends it at any time and puts the valve back as it was. Start the test?</source>
            <translation>Dieser Test bewegt den Schieber (und bei E04 den Antrieb): %1.

Stellen Sie sicher, dass die Hydraulik dafür sicher ist. Stopp beendet ihn jederzeit und stellt das Ventil wieder her, wie es war. Test starten?</translation>
        </message>
        <message>
            <source>Tuning</source>
            <translation>Einstellung</translation>
        </message>
        <message>
            <source>The oscilloscope's setpoint generator was stopped for the test.</source>
            <translation>Der Sollwertgenerator des Oszilloskops wurde für die Prüfung angehalten.</translation>
        </message>
        <message>
            <source>Not started: the valve does not follow its setpoint: %1</source>
            <translation>Nicht gestartet: das Ventil folgt seinem Sollwert nicht: %1</translation>
        </message>
        <message>
            <source>At the present access level the result of this test cannot be accepted: %1

Switch to Expert first (View → Access level), or run the test now and switch before you accept: its result is kept. Start the test anyway?</source>
            <translation>Auf der jetzigen Berechtigungsstufe kann das Ergebnis dieses Tests nicht übernommen werden: %1

Wechseln Sie zuerst zu Experte (Ansicht → Berechtigungsstufe) oder starten Sie den Test jetzt und wechseln Sie vor dem Übernehmen: sein Ergebnis bleibt erhalten. Den Test trotzdem starten?</translation>
        </message>
        <message>
            <source>The oscilloscope's setpoint generator is running: the test stops it (start it again afterwards).</source>
            <translation>Der Sollwertgenerator des Oszilloskops läuft: Die Prüfung hält ihn an (danach erneut starten).</translation>
        </message>
        <message>
            <source>Stopping…</source>
            <translation>Wird abgebrochen…</translation>
        </message>
        <message>
            <source>Done.</source>
            <translation>Fertig.</translation>
        </message>
        <message>
            <source>Stopped: %1</source>
            <translation>Abgebrochen: %1</translation>
        </message>
        <message>
            <source>(View → Access level)</source>
            <translation>(Ansicht → Berechtigungsstufe)</translation>
        </message>
        <message>
            <source>Not accepted: %1</source>
            <translation>Nicht übernommen: %1</translation>
        </message>
        <message>
            <source>Accepted: %1</source>
            <translation>Übernommen: %1</translation>
        </message>
        <message>
            <source>Tuning and characterization</source>
            <translation>Einstellung und Charakterisierung</translation>
        </message>
        <message>
            <source>Position controller (spool)</source>
            <translation>Lageregler (Schieber)</translation>
        </message>
        <message>
            <source>Process controller (E04)</source>
            <translation>Prozessregler (E04)</translation>
        </message>
        <message>
            <source>Loop:</source>
            <translation>Regelkreis:</translation>
        </message>
        <message>
            <source>Stop</source>
            <translation>Stopp</translation>
        </message>
        <message>
            <source>Offline: the tests run on the twin of serial {0} (fitted {1}, {2}) with the document's values.</source>
            <translation>Offline: Die Tests laufen auf dem Zwilling der Seriennummer {0} (angepasst {1}, {2}) mit den Werten des Dokuments.</translation>
        </message>
        <message>
            <source>Offline: the tests run on an emulated valve with the document's values.</source>
            <translation>Offline: Die Tests laufen auf einem emulierten Ventil mit den Werten des Dokuments.</translation>
        </message>
        <message>
            <source>The emulator's plant: this serial has no twin in the history.</source>
            <translation>Strecke des Emulators: Diese Seriennummer hat keinen Zwilling im Verlauf.</translation>
        </message>
        <message>
            <source>Online: the tests move the connected valve.</source>
            <translation>Online: Die Tests bewegen das angeschlossene Ventil.</translation>
        </message>
        <message>
            <source>Autotune</source>
            <translation>Autotune</translation>
        </message>
        <message>
            <source>Frequency response</source>
            <translation>Frequenzgang</translation>
        </message>
        <message>
            <source>Static characteristic</source>
            <translation>Statische Kennlinie</translation>
        </message>
        <message>
            <source>Test report</source>
            <translation>Prüfbericht</translation>
        </message>
        <message>
            <source>Ready.</source>
            <translation>Bereit.</translation>
        </message>
        <message>
            <source>Birth certificate</source>
            <translation>Geburtsurkunde</translation>
        </message>
        <message>
            <source>Twin</source>
            <translation>Zwilling</translation>
        </message>
        <message>
            <source>Flow characteristic (E04)</source>
            <translation>Durchflusskennlinie (E04)</translation>
        </message>
    </context>
    <context>
        <name>TwinPage</name>
        <message>
            <source>Save the twin file</source>
            <translation>Zwillingsdatei speichern</translation>
        </message>
        <message>
            <source>Twin file (*.toml)</source>
            <translation>Zwillingsdatei (*.toml)</translation>
        </message>
        <message>
            <source>There is no folder %1 for the twin file.</source>
            <translation>Für die Zwillingsdatei gibt es keinen Ordner %1.</translation>
        </message>
        <message>
            <source>A twin is fitted to a valve's own measurement: go online with the valve, or fit it from a characterization report (Fit from a report…).</source>
            <translation>Ein Zwilling wird an die Messung eines Ventils selbst angepasst: gehen Sie mit dem Ventil online oder passen Sie ihn an einen Charakterisierungsbericht an (Aus einem Bericht anpassen…).</translation>
        </message>
        <message>
            <source>the end-of-line test (steps, a sine sweep and a triangle, about %1 s), then the twin fitted to it</source>
            <translation>die Endprüfung (Sprünge, ein Sinus-Sweep und ein Dreieck, etwa %1 s), danach der daran angepasste Zwilling</translation>
        </message>
        <message>
            <source>Characterization report</source>
            <translation>Charakterisierungsbericht</translation>
        </message>
        <message>
            <source>JSON report (*.json)</source>
            <translation>JSON-Bericht (*.json)</translation>
        </message>
        <message>
            <source>Fitting the twin of %1…</source>
            <translation>Zwilling aus %1 wird angepasst…</translation>
        </message>
        <message>
            <source>Not fitted: %1</source>
            <translation>Nicht angepasst: %1</translation>
        </message>
        <message>
            <source>explained by the plant structure</source>
            <translation>von der Struktur der Strecke erklärt</translation>
        </message>
        <message>
            <source>NOT explained by the plant structure: its constants are the best it allows</source>
            <translation>NICHT von der Struktur der Strecke erklärt: ihre Konstanten sind das Beste, was sie zulässt</translation>
        </message>
        <message>
            <source>Twin written to %1 and recorded in the history. Residual %2 % → %3 % rms (%4).</source>
            <translation>Zwilling in %1 geschrieben und im Verlauf festgehalten. Residuum %2 % → %3 % rms (%4).</translation>
        </message>
        <message>
            <source>Fitted: %1.</source>
            <translation>Angepasst: %1.</translation>
        </message>
        <message>
            <source>The twin could not be characterized: %1</source>
            <translation>Der Zwilling konnte nicht charakterisiert werden: %1</translation>
        </message>
        <message>
            <source>The twin was characterized over: %1.</source>
            <translation>Der Zwilling wurde charakterisiert über: %1.</translation>
        </message>
        <message>
            <source>determined</source>
            <translation>bestimmt</translation>
        </message>
        <message>
            <source>not determined, kept</source>
            <translation>nicht bestimmt, beibehalten</translation>
        </message>
        <message>
            <source>(seen only with %1)</source>
            <translation>(nur zusammen mit %1 sichtbar)</translation>
        </message>
        <message>
            <source>%1 pp (twin − valve)</source>
            <translation>%1 Pp (Zwilling − Ventil)</translation>
        </message>
        <message>
            <source>×%1 (twin/valve)</source>
            <translation>×%1 (Zwilling/Ventil)</translation>
        </message>
        <message>
            <source>steps</source>
            <translation>Sprünge</translation>
        </message>
        <message>
            <source>sweep</source>
            <translation>Sweep</translation>
        </message>
        <message>
            <source>static characteristic</source>
            <translation>statische Kennlinie</translation>
        </message>
        <message>
            <source>A twin is the emulator's plant with the constants of this valve, fitted to its characterization (steps, sweep and static characteristic) and kept in a twin file with its serial and parameter set (docs/twin.md). Fit twin of the valve runs the end-of-line test of the profile chosen on the Test report page on the connected valve; Fit from a report… takes a characterization's JSON report (prm9tool --characterize --json) and its CSV files. Both record the twin in the history for the serial; offline tuning then runs on it.</source>
            <translation>Ein Zwilling ist die Strecke des Emulators mit den Konstanten dieses Ventils, angepasst an seine Charakterisierung (Sprünge, Sweep und statische Kennlinie) und in einer Zwillingsdatei mit seiner Seriennummer und seinem Parametersatz abgelegt (docs/twin.md). „Zwilling des Ventils anpassen“ führt die Endprüfung des auf der Seite Prüfbericht gewählten Profils am verbundenen Ventil aus; „Aus einem Bericht anpassen…“ nimmt den JSON-Bericht einer Charakterisierung (prm9tool --characterize --json) mit seinen CSV-Dateien. Beide halten den Zwilling im Verlauf der Seriennummer fest; die Offline-Abstimmung läuft dann auf ihm.</translation>
        </message>
        <message>
            <source>Twin file:</source>
            <translation>Zwillingsdatei:</translation>
        </message>
        <message>
            <source>Browse…</source>
            <translation>Durchsuchen…</translation>
        </message>
        <message>
            <source>Fit twin of the valve</source>
            <translation>Zwilling des Ventils anpassen</translation>
        </message>
        <message>
            <source>Fit from a report…</source>
            <translation>Aus einem Bericht anpassen…</translation>
        </message>
        <message>
            <source>Constant</source>
            <translation>Konstante</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>Start</translation>
        </message>
        <message>
            <source>Fitted</source>
            <translation>Angepasst</translation>
        </message>
        <message>
            <source>Data</source>
            <translation>Daten</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>Kennwert</translation>
        </message>
        <message>
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
        <message>
            <source>Twin</source>
            <translation>Zwilling</translation>
        </message>
        <message>
            <source>Twin compared with valve</source>
            <translation>Zwilling verglichen mit dem Ventil</translation>
        </message>
    </context>
    <context>
        <name>TypeKey</name>
        <message>
            <source>spool catalogue {0}: {1}</source>
            <translation>Schieberkatalog {0}: {1}</translation>
        </message>
        <message>
            <source>spool catalogue {0}: entry {1}: {2}</source>
            <translation>Schieberkatalog {0}: Eintrag {1}: {2}</translation>
        </message>
        <message>
            <source>expected a list of spools</source>
            <translation>erwartet wird eine Liste von Schiebern</translation>
        </message>
        <message>
            <source>expected an object with code, coils and description</source>
            <translation>erwartet wird ein Objekt mit code, coils und description</translation>
        </message>
        <message>
            <source>{0} is missing</source>
            <translation>{0} fehlt</translation>
        </message>
        <message>
            <source>code {0} must be letters and digits only</source>
            <translation>code {0} darf nur Buchstaben und Ziffern enthalten</translation>
        </message>
        <message>
            <source>spool {0} is named in the manual and cannot be redefined</source>
            <translation>Schieber {0} ist im Handbuch genannt und kann nicht neu definiert werden</translation>
        </message>
        <message>
            <source>coils {0} must be AB, A or B</source>
            <translation>coils {0} muss AB, A oder B sein</translation>
        </message>
        <message>
            <source>type key {0}: must start with 'PRM9-'</source>
            <translation>Typschlüssel {0}: muss mit 'PRM9-' beginnen</translation>
        </message>
        <message>
            <source>type key {0}: nominal size {1} must be 06 or 10</source>
            <translation>Typschlüssel {0}: Nenngröße {1} muss 06 oder 10 sein</translation>
        </message>
        <message>
            <source>type key {0}: unknown spool {1} (known: {2})</source>
            <translation>Typschlüssel {0}: unbekannter Schieber {1} (bekannt: {2})</translation>
        </message>
        <message>
            <source>type key {0}: flow {1} l/min does not exist for Dn{2} (allowed: {3})</source>
            <translation>Typschlüssel {0}: Nennvolumenstrom {1} l/min gibt es bei Dn{2} nicht (zulässig: {3})</translation>
        </message>
        <message>
            <source>type key {0}: supply voltage {1} must be 24</source>
            <translation>Typschlüssel {0}: Versorgungsspannung {1} muss 24 sein</translation>
        </message>
        <message>
            <source>type key {0}: configuration {1} must be E02 or E04</source>
            <translation>Typschlüssel {0}: Konfiguration {1} muss E02 oder E04 sein</translation>
        </message>
        <message>
            <source>type key {0}: suffix {1} must be empty or -CA</source>
            <translation>Typschlüssel {0}: Zusatz {1} muss leer oder -CA sein</translation>
        </message>
        <message>
            <source>type key {0}: expected '-' between the electronics series S02 and {1}</source>
            <translation>Typschlüssel {0}: Zwischen der Elektronik-Baureihe S02 und {1} fehlt '-'</translation>
        </message>
        <message>
            <source>type key {0}: electronics series {1} must be S02</source>
            <translation>Typschlüssel {0}: Elektronik-Baureihe {1} muss S02 sein</translation>
        </message>
        <message>
            <source>type key {0}: expected '.' between the nominal size {1} and the spool, found {2}</source>
            <translation>Typschlüssel {0}: Zwischen Nenngröße {1} und Schieber wird '.' erwartet, gefunden: {2}</translation>
        </message>
        <message>
            <source>type key {0}: expected '/' between the spool {1} and the nominal flow, found {2}</source>
            <translation>Typschlüssel {0}: Zwischen Schieber {1} und Nennvolumenstrom wird '/' erwartet, gefunden: {2}</translation>
        </message>
        <message>
            <source>type key {0}: expected '-' between the nominal flow {1} and the supply voltage, found {2}</source>
            <translation>Typschlüssel {0}: Zwischen Nennvolumenstrom {1} und Versorgungsspannung wird '-' erwartet, gefunden: {2}</translation>
        </message>
        <message>
            <source>the end of the key</source>
            <translation>das Ende des Schlüssels</translation>
        </message>
        <message>
            <source>type key {0}: the {1} is missing</source>
            <translation>Typschlüssel {0}: {1} fehlt</translation>
        </message>
        <message>
            <source>nominal size (06 or 10)</source>
            <translation>die Nenngröße (06 oder 10)</translation>
        </message>
        <message>
            <source>spool</source>
            <translation>der Schieber</translation>
        </message>
        <message>
            <source>nominal flow</source>
            <translation>der Nennvolumenstrom</translation>
        </message>
        <message>
            <source>supply voltage (24)</source>
            <translation>die Versorgungsspannung (24)</translation>
        </message>
        <message>
            <source>configuration (E02 or E04)</source>
            <translation>die Konfiguration (E02 oder E04)</translation>
        </message>
        <message>
            <source>electronics series (S02)</source>
            <translation>die Elektronik-Baureihe (S02)</translation>
        </message>
    </context>
    <context>
        <name>ValveConnection</name>
        <message>
            <source>The valve connection is busy; wait until it is done.</source>
            <translation>Die Verbindung zum Ventil ist beschäftigt; warten Sie, bis sie fertig ist.</translation>
        </message>
        <message>
            <source>Already online; go offline first.</source>
            <translation>Bereits online; zuerst offline gehen.</translation>
        </message>
        <message>
            <source>Not connected to a valve.</source>
            <translation>Nicht mit einem Ventil verbunden.</translation>
        </message>
    </context>
    <context>
        <name>ValveControl</name>
        <message>
            <source>it is operational on CANopen but not enabled yet (device state {0}). Press Enable (control word 08h → 09h → 0Bh → 0Fh).</source>
            <translation>es ist am CANopen-Bus operational, aber noch nicht freigegeben (Gerätezustand {0}). Drücken Sie „Freigeben“ (Steuerwort 08h → 09h → 0Bh → 0Fh).</translation>
        </message>
        <message>
            <source>no valve is connected.</source>
            <translation>kein Ventil ist verbunden.</translation>
        </message>
        <message>
            <source>the valve is starting up (about 2 s).</source>
            <translation>das Ventil startet (etwa 2 s).</translation>
        </message>
        <message>
            <source>an error stops it (device state {0}); Valve → Valve status lists the error and resets it with Enable once the cause is gone.</source>
            <translation>ein Fehler hält es an (Gerätezustand {0}); Ventil → Ventilstatus zeigt den Fehler und setzt ihn mit „Freigeben“ zurück, sobald die Ursache behoben ist.</translation>
        </message>
        <message>
            <source>it waits for a CANopen master (NMT {0}, device state {1}). Enable it under Valve → Valve status (control word 08h → 09h → 0Bh → 0Fh).</source>
            <translation>es wartet auf einen CANopen-Master (NMT {0}, Gerätezustand {1}). Geben Sie es unter Ventil → Ventilstatus frei (Steuerwort 08h → 09h → 0Bh → 0Fh).</translation>
        </message>
        <message>
            <source>its CANopen master stopped it (NMT stopped). Start it under Valve → Valve status.</source>
            <translation>sein CANopen-Master hat es angehalten (NMT gestoppt). Starten Sie es unter Ventil → Ventilstatus.</translation>
        </message>
        <message>
            <source>it is not enabled (device state {0}). Enable it under Valve → Valve status.</source>
            <translation>es ist nicht freigegeben (Gerätezustand {0}). Geben Sie es unter Ventil → Ventilstatus frei.</translation>
        </message>
        <message>
            <source>it holds its position (device state HOLD). Enable it under Valve → Valve status.</source>
            <translation>es hält seine Position (Gerätezustand HOLD). Geben Sie es unter Ventil → Ventilstatus frei.</translation>
        </message>
        <message>
            <source>an error stops it (device state {0}); the list of errors shows it. Press Enable once the cause is gone.</source>
            <translation>ein Fehler hält es an (Gerätezustand {0}); die Fehlerliste zeigt ihn. Drücken Sie „Freigeben“, sobald die Ursache behoben ist.</translation>
        </message>
        <message>
            <source>it waits for a CANopen master (NMT {1}, device state {0}). Press NMT start, then Enable (control word 08h → 09h → 0Bh → 0Fh).</source>
            <translation>es wartet auf einen CANopen-Master (NMT {1}, Gerätezustand {0}). Drücken Sie „NMT Start“, dann „Freigeben“ (Steuerwort 08h → 09h → 0Bh → 0Fh).</translation>
        </message>
        <message>
            <source>its CANopen master stopped it (NMT stopped). Press NMT start.</source>
            <translation>sein CANopen-Master hat es angehalten (NMT gestoppt). Drücken Sie „NMT Start“.</translation>
        </message>
        <message>
            <source>it is not enabled (device state {0}). Press Enable.</source>
            <translation>es ist nicht freigegeben (Gerätezustand {0}). Drücken Sie „Freigeben“.</translation>
        </message>
        <message>
            <source>it holds its position (device state HOLD). Press Enable.</source>
            <translation>es hält seine Position (Gerätezustand HOLD). Drücken Sie „Freigeben“.</translation>
        </message>
        <message>
            <source>offline</source>
            <translation>offline</translation>
        </message>
        <message>
            <source>starting up</source>
            <translation>startet</translation>
        </message>
        <message>
            <source>fault</source>
            <translation>Fehler</translation>
        </message>
        <message>
            <source>waiting for a CANopen master</source>
            <translation>wartet auf CANopen-Master</translation>
        </message>
        <message>
            <source>NMT stopped</source>
            <translation>NMT gestoppt</translation>
        </message>
        <message>
            <source>not enabled</source>
            <translation>nicht freigegeben</translation>
        </message>
        <message>
            <source>hold</source>
            <translation>Halten</translation>
        </message>
    </context>
    <context>
        <name>ValveFinder</name>
        <message>
            <source>Listing the valves failed: {0}</source>
            <translation>Auflisten der Ventile fehlgeschlagen: {0}</translation>
        </message>
        <message>
            <source>Looking for valves…</source>
            <translation>Ventile werden gesucht…</translation>
        </message>
        <message>
            <source>Connecting to {0}…</source>
            <translation>Verbinden mit {0}…</translation>
        </message>
    </context>
    <context>
        <name>ValveRestarts</name>
        <message>
            <source>Restoring the factory values…</source>
            <translation>Werkseinstellungen werden wiederhergestellt…</translation>
        </message>
        <message>
            <source>Restore factory values</source>
            <translation>Werkseinstellungen wiederherstellen</translation>
        </message>
        <message>
            <source>Set every parameter of the document to the factory default?</source>
            <translation>Alle Parameter des Dokuments auf die Werkseinstellung setzen?</translation>
        </message>
        <message>
            <source>Restarting the valve…</source>
            <translation>Ventil wird neu gestartet…</translation>
        </message>
        <message>
            <source>The valve restarted</source>
            <translation>Das Ventil wurde neu gestartet</translation>
        </message>
        <message>
            <source>{0} kbit/s</source>
            <translation>{0} kbit/s</translation>
        </message>
        <message>
            <source>The valve restarted at {0} {1}; prm9tool found it there</source>
            <translation>Das Ventil ist als {0} {1} neu gestartet; prm9tool hat es dort gefunden</translation>
        </message>
        <message>
            <source>Factory values of the valve</source>
            <translation>Werkseinstellungen des Ventils</translation>
        </message>
        <message>
            <source>Factory values restored; the valve's previous parameters are in {0}</source>
            <translation>Werkseinstellungen wiederhergestellt; die bisherigen Parameter des Ventils sind in {0}</translation>
        </message>
        <message>
            <source>Factory values restored; the valve's backup from before is kept</source>
            <translation>Werkseinstellungen wiederhergestellt; die frühere Sicherung des Ventils bleibt erhalten</translation>
        </message>
    </context>
    <context>
        <name>ValveSelectionDialog</name>
        <message>
            <source>Valve selection</source>
            <translation>Ventilauswahl</translation>
        </message>
        <message>
            <source>Choose the valve by its type key. The new parameter set holds the factory defaults of that type; valve-specific calibration data is not included.</source>
            <translation>Wählen Sie das Ventil über seinen Typschlüssel. Der neue Parametersatz enthält die Werkseinstellungen dieses Typs; ventilspezifische Kalibrierdaten sind nicht enthalten.</translation>
        </message>
        <message>
            <source>Nominal size:</source>
            <translation>Nenngröße:</translation>
        </message>
        <message>
            <source>Spool:</source>
            <translation>Schieber:</translation>
        </message>
        <message>
            <source>Nominal flow (Δp 10 bar):</source>
            <translation>Nennvolumenstrom (Δp 10 bar):</translation>
        </message>
        <message>
            <source>Supply voltage:</source>
            <translation>Versorgungsspannung:</translation>
        </message>
        <message>
            <source>Configuration:</source>
            <translation>Konfiguration:</translation>
        </message>
        <message>
            <source>Interface:</source>
            <translation>Schnittstelle:</translation>
        </message>
        <message>
            <source>Type key:</source>
            <translation>Typschlüssel:</translation>
        </message>
        <message>
            <source>E02 – internal position feedback</source>
            <translation>E02 – interne Lagerückführung</translation>
        </message>
        <message>
            <source>E04 – internal position and external feedback</source>
            <translation>E04 – interne Lage- und externe Rückführung</translation>
        </message>
        <message>
            <source> (assumption)</source>
            <translation> (Annahme)</translation>
        </message>
        <message>
            <source> (your spools.json)</source>
            <translation> (Ihre spools.json)</translation>
        </message>
        <message>
            <source>two solenoids A and B</source>
            <translation>zwei Spulen A und B</translation>
        </message>
        <message>
            <source>one solenoid on side {0}</source>
            <translation>eine Spule auf Seite {0}</translation>
        </message>
    </context>
    <context>
        <name>ValveStatusWindow</name>
        <message>
            <source>Valve status</source>
            <translation>Ventilstatus</translation>
        </message>
        <message>
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
        <message>
            <source>Active errors</source>
            <translation>Aktive Fehler</translation>
        </message>
        <message>
            <source>LEDs</source>
            <translation>LEDs</translation>
        </message>
        <message>
            <source>Mode:</source>
            <translation>Modus:</translation>
        </message>
        <message>
            <source>Firmware version:</source>
            <translation>Firmware-Version:</translation>
        </message>
        <message>
            <source>Serial number:</source>
            <translation>Seriennummer:</translation>
        </message>
        <message>
            <source>Type key:</source>
            <translation>Typschlüssel:</translation>
        </message>
        <message>
            <source>Device state:</source>
            <translation>Gerätezustand:</translation>
        </message>
        <message>
            <source>CANopen NMT state:</source>
            <translation>CANopen-NMT-Zustand:</translation>
        </message>
        <message>
            <source>Temperature:</source>
            <translation>Temperatur:</translation>
        </message>
        <message>
            <source>Supply voltage:</source>
            <translation>Versorgungsspannung:</translation>
        </message>
        <message>
            <source>LED 1 power</source>
            <translation>LED 1 Versorgung</translation>
        </message>
        <message>
            <source>LED 2 error</source>
            <translation>LED 2 Fehler</translation>
        </message>
        <message>
            <source>LED 3 CAN</source>
            <translation>LED 3 CAN</translation>
        </message>
        <message>
            <source>ONLINE</source>
            <translation>ONLINE</translation>
        </message>
        <message>
            <source>OFFLINE</source>
            <translation>OFFLINE</translation>
        </message>
        <message>
            <source>No status: the valve is offline.</source>
            <translation>Kein Status: Das Ventil ist offline.</translation>
        </message>
        <message>
            <source>off (no CANopen)</source>
            <translation>aus (kein CANopen)</translation>
        </message>
        <message>
            <source>initialising</source>
            <translation>Initialisierung</translation>
        </message>
        <message>
            <source>unknown</source>
            <translation>unbekannt</translation>
        </message>
        <message>
            <source>white</source>
            <translation>weiß</translation>
        </message>
        <message>
            <source>green</source>
            <translation>grün</translation>
        </message>
        <message>
            <source>orange</source>
            <translation>orange</translation>
        </message>
        <message>
            <source>red</source>
            <translation>rot</translation>
        </message>
        <message>
            <source>blue</source>
            <translation>blau</translation>
        </message>
        <message>
            <source>magenta</source>
            <translation>magenta</translation>
        </message>
        <message>
            <source>on</source>
            <translation>leuchtet</translation>
        </message>
        <message>
            <source>blinking 1 Hz</source>
            <translation>blinkt 1 Hz</translation>
        </message>
        <message>
            <source>blinking 2 Hz</source>
            <translation>blinkt 2 Hz</translation>
        </message>
        <message>
            <source>blinking 2.5 Hz</source>
            <translation>blinkt 2,5 Hz</translation>
        </message>
        <message>
            <source>single flash</source>
            <translation>Einfachblitz</translation>
        </message>
        <message>
            <source>double flash</source>
            <translation>Doppelblitz</translation>
        </message>
        <message>
            <source>triple flash</source>
            <translation>Dreifachblitz</translation>
        </message>
        <message>
            <source>quadruple flash</source>
            <translation>Vierfachblitz</translation>
        </message>
        <message>
            <source>power-up</source>
            <translation>Einschalten</translation>
        </message>
        <message>
            <source>off</source>
            <translation>aus</translation>
        </message>
        <message>
            <source>No error is present any more, but the valve still holds the fault (device state {0}): press Enable (control word 08h → 09h → 0Bh → 0Fh) to reset it.</source>
            <translation>Es liegt kein Fehler mehr an, aber das Ventil hält den Fehlerzustand noch (Gerätezustand {0}): drücken Sie Freigeben (Steuerwort 08h → 09h → 0Bh → 0Fh), um ihn zurückzusetzen.</translation>
        </message>
        <message>
            <source>No error.</source>
            <translation>Kein Fehler.</translation>
        </message>
    </context>
    <context>
        <name>ValveUpload</name>
        <message>
            <source>Nothing was sent to the valve</source>
            <translation>Es wurde nichts an das Ventil gesendet</translation>
        </message>
        <message>
            <source>Upload to valve</source>
            <translation>In das Ventil hochladen</translation>
        </message>
        <message>
            <source>The document is for a {0} valve, the connected valve is a {1} valve. Choose the matching valve type or download the valve's parameters first.</source>
            <translation>Das Dokument ist für ein Ventil {0}, das angeschlossene Ventil ist ein Ventil {1}. Wählen Sie den passenden Ventiltyp oder laden Sie zuerst die Parameter des Ventils herunter.</translation>
        </message>
        <message>
            <source>Uploading the parameters to the valve…</source>
            <translation>Parameter werden in das Ventil hochgeladen…</translation>
        </message>
        <message>
            <source>Expert values at Basic level</source>
            <translation>Expertenwerte in der Basisstufe</translation>
        </message>
        <message numerus="yes">
            <source>The document changes %n Expert-level value(s) of the valve ({0}), which the Basic access level cannot edit (controllers, linearizations, monitoring). Send them anyway?</source>
            <translation>
                <numerusform>Das Dokument ändert %n Expertenwert des Ventils ({0}), den die Basisstufe nicht bearbeiten kann (Regler, Linearisierungen, Überwachung). Trotzdem senden?</numerusform>
                <numerusform>Das Dokument ändert %n Expertenwerte des Ventils ({0}), die die Basisstufe nicht bearbeiten kann (Regler, Linearisierungen, Überwachung). Trotzdem senden?</numerusform>
            </translation>
        </message>
        <message>
            <source>Values written to the valve</source>
            <translation>In das Ventil geschriebene Werte</translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) written, verified and stored at {0}</source>
            <translation>
                <numerusform>%n Parameter um {0} geschrieben, geprüft und gespeichert</numerusform>
                <numerusform>%n Parameter um {0} geschrieben, geprüft und gespeichert</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) written, verified and stored again at {0}: the valve already held them</source>
            <translation>
                <numerusform>%n Parameter um {0} erneut geschrieben, geprüft und gespeichert: Das Ventil hatte ihn schon</numerusform>
                <numerusform>%n Parameter um {0} erneut geschrieben, geprüft und gespeichert: Das Ventil hatte sie schon</numerusform>
            </translation>
        </message>
        <message>
            <source>; Valve → Verify by restart… checks that it keeps them</source>
            <translation>; Ventil → Durch Neustart prüfen… prüft, ob es sie behält</translation>
        </message>
        <message>
            <source>stored with 0x1010</source>
            <translation>mit 0x1010 gespeichert</translation>
        </message>
        <message>
            <source>kept by the valve as written (it has no store command)</source>
            <translation>vom Ventil wie geschrieben behalten (es hat keinen Speicherbefehl)</translation>
        </message>
        <message>
            <source>verified after a restart</source>
            <translation>nach einem Neustart geprüft</translation>
        </message>
        <message>
            <source>Upload failed</source>
            <translation>Hochladen fehlgeschlagen</translation>
        </message>
        <message>
            <source>The upload failed at step “{0}”. Nothing was stored: after a restart the valve holds its previous parameters.</source>
            <translation>Das Hochladen ist im Schritt „{0}“ fehlgeschlagen. Nichts wurde gespeichert: nach einem Neustart hat das Ventil seine vorherigen Parameter.</translation>
        </message>
    </context>
    <context>
        <name>ValveWorkflow</name>
        <message>
            <source>Store changes in the valve</source>
            <translation>Änderungen im Ventil speichern</translation>
        </message>
        <message>
            <source>Values changed online are active in the valve but not stored: a restart of the valve would undo them. Store them in the valve now?</source>
            <translation>Online geänderte Werte sind im Ventil aktiv, aber nicht gespeichert: Ein Neustart des Ventils würde sie rückgängig machen. Jetzt im Ventil speichern?</translation>
        </message>
        <message>
            <source>Offline</source>
            <translation>Offline</translation>
        </message>
        <message>
            <source>Reading the valve's parameters…</source>
            <translation>Parameter des Ventils werden gelesen…</translation>
        </message>
        <message>
            <source>Back online: document and valve agree</source>
            <translation>Wieder online: Dokument und Ventil stimmen überein</translation>
        </message>
        <message>
            <source>Online: document and valve agree</source>
            <translation>Online: Dokument und Ventil stimmen überein</translation>
        </message>
        <message>
            <source>Another valve</source>
            <translation>Anderes Ventil</translation>
        </message>
        <message>
            <source>The document was read from valve {0}; you are online with valve {1} (serial numbers). Continue with this document on valve {1}?

Yes compares the two as usual (nothing is written unasked); No goes offline.</source>
            <translation>Das Dokument wurde aus Ventil {0} gelesen; online sind Sie mit Ventil {1} (Seriennummern). Mit diesem Dokument an Ventil {1} weiterarbeiten?

Ja vergleicht beide wie gewohnt (ohne Rückfrage wird nichts geschrieben); Nein geht offline.</translation>
        </message>
        <message>
            <source>Values read from the valve</source>
            <translation>Aus dem Ventil gelesene Werte</translation>
        </message>
        <message>
            <source>Online: parameters read from the valve</source>
            <translation>Online: Parameter aus dem Ventil gelesen</translation>
        </message>
        <message>
            <source>{0}: the valve is a {1}, so the document is a new, unsaved one ({2} stays as it is)</source>
            <translation>{0}: das Ventil ist ein {1}, daher ist das Dokument ein neues, ungespeichertes ({2} bleibt unverändert)</translation>
        </message>
        <message>
            <source>The valve reports an unknown type key: {0}</source>
            <translation>Das Ventil meldet einen unbekannten Typschlüssel: {0}</translation>
        </message>
        <message>
            <source>Nothing was sent to the valve</source>
            <translation>Es wurde nichts an das Ventil gesendet</translation>
        </message>
        <message>
            <source>Storing the parameters in the valve…</source>
            <translation>Parameter werden im Ventil gespeichert…</translation>
        </message>
        <message>
            <source>Downloading the parameters from the valve…</source>
            <translation>Parameter werden aus dem Ventil heruntergeladen…</translation>
        </message>
        <message>
            <source>The valve's parameters are in the document; File → Save backup copy… keeps a copy of them</source>
            <translation>Ventilparameter im Dokument; sichern mit Datei → Sicherungskopie speichern…</translation>
        </message>
        <message>
            <source>The valve stored its parameters at {0}</source>
            <translation>Das Ventil hat seine Parameter um {0} gespeichert</translation>
        </message>
        <message>
            <source>Download from valve</source>
            <translation>Aus dem Ventil herunterladen</translation>
        </message>
        <message>
            <source>Valve communication</source>
            <translation>Kommunikation mit dem Ventil</translation>
        </message>
        <message>
            <source>Connection to the valve lost; looking for it… ({0})</source>
            <translation>Verbindung zum Ventil verloren; es wird gesucht… ({0})</translation>
        </message>
        <message>
            <source>The connection to the valve was lost; prm9tool is offline now and looks for the valve. When it is back, prm9tool compares it with the document and you decide what to do; nothing is sent again by itself.
Every value is kept in the document.</source>
            <translation>Die Verbindung zum Ventil ist verloren; prm9tool ist jetzt offline und sucht das Ventil. Sobald es wieder da ist, vergleicht prm9tool es mit dem Dokument und Sie entscheiden, was geschieht; nichts wird von selbst erneut gesendet.
Alle Werte bleiben im Dokument erhalten.</translation>
        </message>
        <message>
            <source>Connection to the valve lost</source>
            <translation>Verbindung zum Ventil verloren</translation>
        </message>
        <message>
            <source>The connection to the valve was lost; prm9tool is offline now.
Every value is kept in the document: save it, or go online again and send it.</source>
            <translation>Die Verbindung zum Ventil ist verloren; prm9tool ist jetzt offline.
Alle Werte bleiben im Dokument erhalten: Speichern Sie es oder gehen Sie wieder online und senden Sie es.</translation>
        </message>
        <message>
            <source>The valve {0} is back online; reading its parameters…</source>
            <translation>Das Ventil {0} ist wieder online; seine Parameter werden gelesen…</translation>
        </message>
        <message>
            <source>The valve is open again: what the setpoint generator cut off with the link had changed is as before ({0})</source>
            <translation>Das Ventil ist wieder verbunden: Was der mit der Verbindung abgebrochene Sollwertgenerator geändert hatte, ist wieder wie vorher ({0})</translation>
        </message>
        <message>
            <source>Another valve (serial number {0}) is where the lost valve {1} was ({2}). prm9tool does not connect to it by itself: it is a new valve. Go online to work with it.</source>
            <translation>Wo das verlorene Ventil {1} war ({2}), ist ein anderes Ventil (Seriennummer {0}). prm9tool verbindet sich nicht von selbst damit: Es ist ein neues Ventil. Gehen Sie online, um damit zu arbeiten.</translation>
        </message>
        <message>
            <source>Backup of the valve's parameters saved: {0}</source>
            <translation>Sicherung der Ventilparameter gespeichert: {0}</translation>
        </message>
    </context>
</TS>
