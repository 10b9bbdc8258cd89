# Resource object code (Python 3)
# Created by: object code
# Created by: The Resource Compiler for Qt version 6.11.3
# WARNING! All changes made in this file will be lost!

from PySide6 import QtCore

qt_resource_data = b"\
\x00\x00\x10\x0d\
<\
!DOCTYPE html>\x0a<\
html lang=\x22de\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>CAN-Bus und C\
ANopen</title></\
head>\x0a<body>\x0a<p>\
<a href=\x22help_de\
.html\x22>Hilfe zu \
prm9tool</a></p>\
\x0a<h1>CAN-Bus und\
 CANopen</h1>\x0a<p\
>Ein -CA-Ventil \
spricht auch CAN\
open (Handbuch K\
apitel 7). prm9t\
ool ist dann der\
\x0aCANopen-Master,\
 \xc3\xbcber jeden CAN\
-Adapter, den py\
thon-can unterst\
\xc3\xbctzt (PEAK, Kva\
ser, IXXAT,\x0aVect\
or, CANable/slca\
n, SocketCAN).</\
p>\x0a<h2>\xc3\x9cber CAN\
 online gehen</h\
2>\x0a<ol>\x0a<li>Komm\
unikation \xe2\x86\x92 <b\
>CAN-Bus\xe2\x80\xa6</b>:\
 Schnittstelle, \
Kanal und Bitrat\
e w\xc3\xa4hlen, dann\x0a\
<b>Bus durchsuch\
en</b>. Jeder an\
twortende Knoten\
 wird mit NMT-Zu\
stand, Heartbeat\
 und letzter\x0aEMC\
Y aufgelistet; K\
noten, die keine\
 PRM9-Ventile si\
nd, lassen sich \
nicht w\xc3\xa4hlen.</\
li>\x0a<li>Ventil w\
\xc3\xa4hlen und OK dr\
\xc3\xbccken: Das Prog\
ramm geht mit ih\
m online (<code>\
can:KNOTEN</code\
>).\x0aEin reales V\
entil nennt sein\
en vollst\xc3\xa4ndige\
n Typschl\xc3\xbcssel \
nicht: Geben Sie\
 den vom Typensc\
hild\x0aein; er wir\
d je Seriennumme\
r gespeichert.</\
li>\x0a</ol>\x0a<h2>In\
betriebnahme</h2\
>\x0a<p>Ein -CA-Ven\
til wartet im Au\
slieferungszusta\
nd auf seinen Ma\
ster: NMT pre-op\
erational,\x0aGer\xc3\xa4\
tezustand INIT; \
es folgt seinem \
Sollwert nicht. \
Ventil \xe2\x86\x92 <b>Ve\
ntilstatus</b>, \
Gruppe\x0aInbetrieb\
nahme: <b>NMT St\
art</b>, dann <b\
>Freigeben</b> d\
r\xc3\xbccken (Steuerw\
ort 08h \xe2\x86\x92 09h \
\xe2\x86\x92 0Bh\x0a\xe2\x86\x92 0Fh)\
. Die Zeile unte\
r den Schaltfl\xc3\xa4\
chen sagt, was n\
och fehlt. \xe2\x80\x9eSp\
erren\xe2\x80\x9c und \xe2\x80\x9e\
NMT Stopp\xe2\x80\x9c\x0aneh\
men es zur\xc3\xbcck.<\
/p>\x0a<h2>Objekte \
und Konfiguratio\
n</h2>\x0a<ul>\x0a<li>\
Ansicht \xe2\x86\x92 <b>O\
bjektverzeichnis\
\xe2\x80\xa6</b> liest je\
des Objekt; in d\
er Suchzeile fin\
den Sie einen\x0aIn\
dex, einen Namen\
 oder einen Wert\
. In der Experte\
nstufe schreibt \
ein Doppelklick \
ein\x0abeschreibbar\
es Objekt.</li>\x0a\
<li>Ansicht \xe2\x86\x92 \
<b>CANopen-Fenst\
er</b>: Node-ID,\
 Bitrate und Abs\
chlusswiderstand\
. Das Ventil\x0alie\
st seine Drehsch\
alter beim Einsc\
halten; eine ge\xc3\
\xa4nderte Node-ID \
oder Bitrate gil\
t nach einem\x0aNeu\
start, und nach \
Ventil \xe2\x86\x92 Venti\
l neu starten fi\
ndet prm9tool da\
s Ventil an sein\
er neuen\x0aAdresse\
.</li>\x0a<li>Datei\
 \xe2\x86\x92 <b>DCF expo\
rtieren\xe2\x80\xa6</b> s\
peichert die Kon\
figuration des V\
entils f\xc3\xbcr ein\x0a\
SPS-Konfiguratio\
nswerkzeug.</li>\
\x0a<li>Ventil \xe2\x86\x92 \
<b>Im Ventil spe\
ichern</b> speic\
hert die Werte, \
mit denen das Ve\
ntil arbeitet,\x0ad\
auerhaft (Objekt\
 0x1010, oder au\
f dem eigenen We\
g des Ventils, w\
o es fehlt).</li\
>\x0a<li>Ein Ventil\
 ohne Objekt 0x1\
010 (die Objektl\
iste des Handbuc\
hs hat keines) b\
eh\xc3\xa4lt jeden Wer\
t,\x0asobald er ges\
chrieben ist: Da\
s Hochladen schr\
eibt in einer Re\
ihenfolge, die n\
ie eine von den\x0a\
Regeln abgelehnt\
e Kombination hi\
nterl\xc3\xa4sst, lies\
t alles zur\xc3\xbcck \
und meldet \xe2\x80\x9evo\
m Ventil wie\x0ages\
chrieben behalte\
n (es hat keinen\
 Speicherbefehl)\
\xe2\x80\x9c. Ventil \xe2\x86\x92 \
<b>Durch Neustar\
t pr\xc3\xbcfen\xe2\x80\xa6</b>\
\x0astartet es dann\
 neu (NMT Reset \
Node, Hydraulik \
getrennt) und li\
est zur\xc3\xbcck, ob \
es die Werte\x0abeh\
alten hat: \xe2\x80\x9ena\
ch einem Neustar\
t gepr\xc3\xbcft\xe2\x80\x9c.</\
li>\x0a</ul>\x0a<p>Das\
 Oszilloskop nim\
mt die Schieberl\
age aus TPDO1; S\
ollwertgenerator\
 und Einstelltes\
ts\x0asenden den So\
llwert in RPDO1,\
 wie eine SPS.</\
p>\x0a<h2>Den Bus a\
ufzeichnen und l\
esen</h2>\x0a<p>Kom\
munikation \xe2\x86\x92 <\
b>CAN-Bus\xe2\x80\xa6</b>\
 \xe2\x86\x92 <b>Aufzeich\
nen\xe2\x80\xa6</b> schre\
ibt jeden Frame \
des Busses mit\x0as\
einer Zeit in ei\
ne Trace-Datei (\
ASC, BLF, TRC od\
er candump-Log);\
 die Aufzeichnun\
g l\xc3\xa4uft neben\x0aa\
llem, was das Pr\
ogramm auf dem B\
us tut (ein Hoch\
laden, ein Test)\
, bis <b>Aufzeic\
hnung\x0abeenden</b\
>. Kommunikation\
 \xe2\x86\x92 <b>CAN-Trac\
e\xe2\x80\xa6</b> \xc3\xb6ffnet\
 eine solche Dat\
ei, auch eine vo\
n\x0aPCAN-View, CAN\
alyzer oder <cod\
e>candump</code>\
, und liest sie \
in Worten: NMT-B\
efehle und\x0a-Zust\
\xc3\xa4nde je Knoten,\
 SDO-\xc3\x9cbertragun\
gen mit dem Name\
n des Objekts, s\
einem Wert in\x0aAn\
zeigeeinheiten u\
nd einem Abbruch\
 in Worten, PDOs\
 nach dem gerade\
 g\xc3\xbcltigen Mappi\
ng, Steuer-\x0aund \
Statuswort als Z\
ustandswechsel, \
EMCY nach der Fe\
hlertabelle des \
Handbuchs, SYNC-\
Periode und\x0aJitt\
er, LSS. Gefilte\
rt wird nach Kno\
ten und Art; die\
 Liste der Vorf\xc3\
\xa4lle (ein verstu\
mmter Knoten,\x0aei\
n EMCY, ein verl\
assenes DEVICE_M\
ODE_ACTIVE, ein \
SDO-Abbruch) w\xc3\xa4\
hlt ihren Frame \
aus. Auf der\x0aKom\
mandozeile: <cod\
e>prm9tool --rec\
ord trace.asc</c\
ode>, <code>prm9\
tool --decode tr\
ace.asc</code>\x0a(\
<code>--json</co\
de>, <code>--csv\
</code>, <code>-\
-fail-on-inciden\
t</code>) und <c\
ode>prm9tool\x0a--r\
eplay trace.asc<\
/code>.</p>\x0a</bo\
dy>\x0a</html>\x0a\
\x00\x00\x05\xea\
<\
!DOCTYPE html>\x0a<\
html lang=\x22en\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>Compare param\
eter sets</title\
></head>\x0a<body>\x0a\
<p><a href=\x22help\
_en.html\x22>prm9to\
ol help</a></p>\x0a\
<h1>Compare para\
meter sets</h1>\x0a\
<p>The compare v\
iew shows two pa\
rameter sets sid\
e by side in dis\
play units, with\
 the factory\x0adef\
aults as a third\
 column. Bold va\
lues differ.</p>\
\x0a<ul>\x0a<li>File \xe2\
\x86\x92 <b>Compare wi\
th file\xe2\x80\xa6</b>: \
the document aga\
inst a <code>*.p\
rm</code> file (\
the\x0adialog opens\
 in the folder u\
sed last).</li>\x0a\
<li>Valve \xe2\x86\x92 <b\
>Compare with va\
lve</b> (online)\
: the document a\
gainst what the \
valve holds\x0anow.\
</li>\x0a<li>Going \
online with a do\
cument that diff\
ers: <b>Choose p\
er parameter\xe2\x80\xa6<\
/b>.</li>\x0a<li>Va\
lve \xe2\x86\x92 History:\
 two records sel\
ected, <b>Compar\
e the two select\
ed records</b>.<\
/li>\x0a</ul>\x0a<h2>P\
utting values ba\
ck</h2>\x0a<ol>\x0a<li\
>Tick the value \
you want in each\
 row (a tick in \
the column of th\
e side it comes \
from), or\x0ause <b\
>Tick every show\
n value of \xe2\x80\xa6</\
b> for the rows \
shown.</li>\x0a<li>\
Press the button\
 that says where\
 the values go: \
<b>Write \xe2\x80\xa6 tic\
ked values into \
the\x0avalve</b> (a\
n upload of exac\
tly those values\
: written, read \
back, compared, \
stored) or\x0a<b>Ta\
ke \xe2\x80\xa6 ticked va\
lues into the do\
cument</b> (one \
undo step). The \
line above the t\
able says\x0awhich \
column to tick f\
or which button;\
 a button stays \
grey until somet\
hing is ticked.<\
/li>\x0a</ol>\x0a<p>Fi\
lters: differenc\
es only, one blo\
ck of the flow d\
iagram, the Basi\
c or Expert leve\
l.\x0aParameters on\
e valve variant \
lacks are shown \
with \xe2\x80\x9c\xe2\x80\x94\xe2\x80\x9d a\
nd cannot be cho\
sen.</p>\x0a</body>\
\x0a</html>\x0a\
\x00\x00\x08\xd4\
<\
!DOCTYPE html>\x0a<\
html lang=\x22de\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>Verlauf eines\
 Ventils</title>\
</head>\x0a<body>\x0a<\
p><a href=\x22help_\
de.html\x22>Hilfe z\
u prm9tool</a></\
p>\x0a<h1>Verlauf e\
ines Ventils</h1\
>\x0a<p>Jeder Vorga\
ng an den Parame\
tern eines Venti\
ls wird mit Zeit\
 (UTC), Seriennu\
mmer,\x0aTypschl\xc3\xbcs\
sel, Firmware, V\
erbindung, Progr\
ammversion, Benu\
tzer und Station\
 festgehalten: L\
esen,\x0aHochladen \
(und wozu), Sich\
erungen, Speiche\
rn, Werkseinstel\
lungen, Pr\xc3\xbcfber\
ichte und was Si\
e\x0aonline getan h\
aben \xe2\x80\x94 Werte a\
us einer verglic\
henen Datei oder\
 aus dem Verlauf\
, \xc3\xbcbernommene\x0aE\
instellungen \xe2\x80\x94\
 mit jedem ge\xc3\xa4n\
derten Wert. Die\
 Eintr\xc3\xa4ge eines\
 Ventils bilden \
eine\x0aHash-Kette;\
 ein ver\xc3\xa4nderte\
r Eintrag f\xc3\xa4llt\
 auf.</p>\x0a<p>Ven\
til \xe2\x86\x92 <b>Verla\
uf\xe2\x80\xa6</b> listet\
 die Eintr\xc3\xa4ge d\
es verbundenen V\
entils (oder ein\
er\x0aeingegebenen \
Seriennummer). D\
ie Spalte <b>Was\
 getan wurde</b>\
 nennt die Bedeu\
tung jedes\x0aEintr\
ags, z. B. \xe2\x80\x9eEi\
nstellung \xc3\xbcbern\
ommen, online ge\
schrieben: Autot\
une; POSKP 0,4 \xe2\
\x86\x92 0,55\xe2\x80\x9c.</p>\x0a\
<ul>\x0a<li><b>Die \
zwei gew\xc3\xa4hlten \
Eintr\xc3\xa4ge vergle\
ichen</b>: der U\
nterschied in de\
r Vergleichsansi\
cht;\x0aWerte ankre\
uzen und in das \
Dokument \xc3\xbcberne\
hmen oder in das\
 Ventil schreibe\
n.</li>\x0a<li><b>I\
n das Dokument \xc3\
\xbcbernehmen</b>: \
der ganze Satz e\
ines Eintrags sa\
mt Typschl\xc3\xbcssel\
\x0a(ein R\xc3\xbcckg\xc3\xa4ng\
ig-Schritt). <b>\
In das Ventil zu\
r\xc3\xbcckschreiben</\
b>: ein transakt\
ionales Hochlade\
n\x0ain das Ventil,\
 von dem der Ein\
trag stammt (onl\
ine mit ihm).</l\
i>\x0a<li><b>Export\
ieren\xe2\x80\xa6</b>: ei\
n Eintrag als <c\
ode>*.prm</code>\
 oder CSV. <b>Da\
tenbank\xe2\x80\xa6</b>:\x0a\
SQLite auf diese\
m Rechner oder e\
in PostgreSQL-Se\
rver f\xc3\xbcr eine L\
inie von Station\
en, und was zu\x0at\
un ist, wenn sie\
 nicht erreichba\
r ist.</li>\x0a</ul\
>\x0a<p>Autotune-L\xc3\
\xa4ufe, Frequenzg\xc3\
\xa4nge, Pr\xc3\xbcfberic\
hte (mit den nic\
ht bestandenen K\
ennwerten und,\x0ae\
inmal gespeicher\
t, dem PDF) und \
Neustarts des Ve\
ntils werden ebe\
nfalls aufgezeic\
hnet. Ein\x0a<b>Dop\
pelklick</b> auf\
 einen Eintrag z\
eigt seine Detai\
ls \xe2\x80\x94 jedes Fel\
d, <b>PDF \xc3\xb6ffne\
n</b>,\x0a<b>Mit de\
m Eintrag davor \
vergleichen</b> \
\xe2\x80\x94 oder, bei zw\
ei gew\xc3\xa4hlten Ei\
ntr\xc3\xa4gen, ihren \
Vergleich.\x0aDer T\
ypenschl\xc3\xbcssel e\
ines Ventils \xc3\xa4n\
dert sich nie: E\
intr\xc3\xa4ge eines a\
nderen Typs unte\
r derselben\x0aSeri\
ennummer (emulie\
rte Ventile zwei\
er L\xc3\xa4ufe k\xc3\xb6nne\
n eine teilen) s\
ind mit \xe2\x9a\xa0 mark\
iert, und das\x0aFe\
nster sagt es.</\
p>\x0a</body>\x0a</htm\
l>\x0a\
\x00\x00$!\
<\
!DOCTYPE html>\x0a<\
html lang=\x22cs\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>prm9tool \xe2\x80\x93 \
n\xc3\xa1pov\xc4\x9bda</titl\
e></head>\x0a<body>\
\x0a<h1>prm9tool</h\
1>\x0a<p>prm9tool n\
astavuje paramet\
ry proporcion\xc3\xa1l\
n\xc3\xadch rozv\xc3\xa1d\xc4\x9b\xc4\
\x8d\xc5\xaf PRM9 s integ\
rovanou digit\xc3\xa1l\
n\xc3\xad\x0aelektronikou\
 \xe2\x80\x93 p\xc5\x99es USB n\
ebo na vestav\xc4\x9bn\
\xc3\xa9m emulovan\xc3\xa9m \
ventilu. Paramet\
ry popisuje p\xc5\x99\xc3\
\xadru\xc4\x8dka\x0aventilu \
(kapitola 8); ta\
to str\xc3\xa1nka popi\
suje program.</p\
>\x0a\x0a<p><b>Dal\xc5\xa1\xc3\xad\
 str\xc3\xa1nky:</b> <\
a href=\x22can_cs.h\
tml\x22>Sb\xc4\x9brnice C\
AN a CANopen</a>\
 \xc2\xb7 <a href=\x22tun\
ing_cs.html\x22>Lad\
\xc4\x9bn\xc3\xad a charakte\
rizace</a> \xc2\xb7 <a\
 href=\x22compare_c\
s.html\x22>Porovn\xc3\xa1\
n\xc3\xad sad parametr\
\xc5\xaf</a> \xc2\xb7 <a hre\
f=\x22history_cs.ht\
ml\x22>Historie ven\
tilu</a>. V okn\xc4\
\x9b otev\xc5\x99e <b>F1<\
/b> str\xc3\xa1nku o n\
\xc4\x9bm.</p>\x0a\x0a<h2>Sp\
u\xc5\xa1t\xc4\x9bn\xc3\xad</h2>\x0a<\
ul>\x0a<li><code>pr\
m9tool</code> ot\
ev\xc5\x99e okno s nov\
\xc3\xbdm z\xc3\xa1znamem pa\
rametr\xc5\xaf.</li>\x0a<\
li><code>prm9too\
l SOUBOR.prm</co\
de> otev\xc5\x99e z\xc3\xa1z\
nam parametr\xc5\xaf.<\
/li>\x0a<li><code>p\
rm9tool --emulat\
or [TYPOV\xc3\x9d_KL\xc3\x8d\
\xc4\x8c[:V\xc3\x9dROBN\xc3\x8d_\xc4\x8c\
\xc3\x8dSLO]]</code> s\
pust\xc3\xad program v\
 re\xc5\xbeimu\x0aonline \
s emulovan\xc3\xbdm ve\
ntilem (v\xc3\xbdchoz\xc3\
\xad typov\xc3\xbd kl\xc3\xad\xc4\x8d\
 <code>PRM9-06.3\
Z11/30-24E02S02-\
CA</code>).</li>\
\x0a</ul>\x0a\x0a<h2>Okno\
</h2>\x0a<p>Hlavn\xc3\xad\
 menu, panel n\xc3\xa1\
stroj\xc5\xaf, hlavn\xc3\xad\
 plocha a stavov\
\xc3\xbd \xc5\x99\xc3\xa1dek. Stav\
ov\xc3\xbd \xc5\x99\xc3\xa1dek zob\
razuje re\xc5\xbeim\x0ako\
munikace, stav e\
lektroniky venti\
lu (<i>ok</i> ne\
bo aktivn\xc3\xad chyb\
u), verzi firmwa\
re, typov\xc3\xbd\x0akl\xc3\xad\
\xc4\x8d a n\xc3\xa1zev soub\
oru; <b>*</b> oz\
na\xc4\x8duje neulo\xc5\xbee\
n\xc3\xa9 zm\xc4\x9bny; nako\
nec \xc3\xbarove\xc5\x88 opr\
\xc3\xa1vn\xc4\x9bn\xc3\xad. Re\xc5\xbei\
m\x0aukazuje P\xc5\x98IPO\
JOV\xc3\x81N\xc3\x8d, dokud \
se pr\xc3\xa1v\xc4\x9b p\xc5\x99ip\
ojen\xc3\xbd ventil po\
rovn\xc3\xa1v\xc3\xa1 se sad\
ou parametr\xc5\xaf, a\
 ONLINE,\x0ajakmile\
 se shoduj\xc3\xad.</p\
>\x0a<p>Hlavn\xc3\xad plo\
cha zobrazuje je\
den ze t\xc5\x99\xc3\xad n\xc3\xa1\
hled\xc5\xaf: <b>postu\
pov\xc3\xbd diagram</b\
> (kliknut\xc3\xadm na\
 blok\x0anastav\xc3\xadte\
 jeho parametry,\
 kliknut\xc3\xadm na \xc4\
\x8derven\xc3\xbd m\xc4\x9b\xc5\x99ic\
\xc3\xad bod jej zobra\
z\xc3\xadte v oscilosk\
opu),\x0a<b>seznam \
parametr\xc5\xaf</b> (\
dvojklikem na \xc5\x99\
\xc3\xa1dek zm\xc4\x9bn\xc3\xadte \
hodnotu; hodnoty\
 odli\xc5\xa1n\xc3\xa9 od to\
v\xc3\xa1rn\xc3\xadho\x0anastav\
en\xc3\xad jsou zv\xc3\xbdra\
zn\xc4\x9bny; hled\xc3\xa1n\xc3\
\xad a \xe2\x80\x9eJen zm\xc4\x9bn\
\xc4\x9bn\xc3\xa9\xe2\x80\x9c seznam \
filtruj\xc3\xad) a <b>\
osciloskop</b>\x0a(\
pouze v re\xc5\xbeimu \
online, nejv\xc3\xbd\xc5\xa1\
e t\xc5\x99i m\xc4\x9b\xc5\x99ic\xc3\xad\
 body).</p>\x0a\x0a<h2\
>\xc3\x9arovn\xc4\x9b opr\xc3\xa1v\
n\xc4\x9bn\xc3\xad</h2>\x0a<p><\
b>Z\xc3\xa1kladn\xc3\xad</b>\
 \xc3\xbarove\xc5\x88 zobraz\
uje z\xc3\xa1kladn\xc3\xad n\
astaven\xc3\xad; na z\xc3\
\xa1kladn\xc3\xad \xc3\xbarovni\
 se \xc4\x8dty\xc5\x99i ramp\
y\x0anastavuj\xc3\xad spo\
le\xc4\x8dn\xc4\x9b. <b>Expe\
rtn\xc3\xad</b> \xc3\xbarove\
\xc5\x88 p\xc5\x99id\xc3\xa1v\xc3\xa1 re\
gul\xc3\xa1tory, linea\
rizace a nastave\
n\xc3\xad\x0aextern\xc3\xadho s\
n\xc3\xadma\xc4\x8de a je ch\
r\xc3\xa1n\xc4\x9bna heslem.\
 Heslo p\xc5\x99i dod\xc3\
\xa1n\xc3\xad je <code>ex\
pert</code>; na \
expertn\xc3\xad\x0a\xc3\xbarovn\
i jej zm\xc4\x9bn\xc3\xadte \
v menu N\xc3\xa1hled \xe2\
\x86\x92 \xc3\x9arove\xc5\x88 opr\xc3\
\xa1vn\xc4\x9bn\xc3\xad \xe2\x86\x92 Zm\xc4\
\x9bnit heslo pro e\
xpertn\xc3\xad \xc3\xbarove\xc5\
\x88.\x0aProgram ukl\xc3\xa1\
d\xc3\xa1 pouze jeho o\
solen\xc3\xbd hash.</p\
>\x0a<p>\xc3\x9arovn\xc4\x9b op\
r\xc3\xa1vn\xc4\x9bn\xc3\xad chr\xc3\xa1\
n\xc3\xad p\xc5\x99ed ne\xc3\xbamy\
sln\xc3\xbdmi zm\xc4\x9bnami\
, ne p\xc5\x99ed t\xc3\xadm,\
 kdo m\xc5\xaf\xc5\xbee upra\
vovat nastaven\xc3\xad\
\x0aprogramu: odstr\
an\xc4\x9bn\xc3\xadm polo\xc5\xbek\
y <code>access/e\
xpert_password</\
code> z nastaven\
\xc3\xad plat\xc3\xad op\xc4\x9bt \
heslo\x0ap\xc5\x99i dod\xc3\xa1\
n\xc3\xad. Soubor para\
metr\xc5\xaf obsahuje \
v\xc5\xa1echny hodnoty\
 bez ohledu na \xc3\
\xbarove\xc5\x88: pokud u\
\xc5\xbeivatel na\x0az\xc3\xa1k\
ladn\xc3\xad \xc3\xbarovni o\
des\xc3\xadl\xc3\xa1 dokumen\
t, jeho\xc5\xbe hodnot\
y expertn\xc3\xad \xc3\xbaro\
vn\xc4\x9b se li\xc5\xa1\xc3\xad o\
d hodnot ventilu\
,\x0aprogram se nej\
prve zept\xc3\xa1.</p>\
\x0a\x0a<h2>Online a o\
ffline</h2>\x0a<p>K\
omunikace \xe2\x86\x92 Ko\
nfigurace HID zo\
braz\xc3\xad ventily p\
\xc5\x99ipojen\xc3\xa9 p\xc5\x99es\
 USB a emulovan\xc3\
\xa9 ventily;\x0aemulo\
van\xc3\xbd ventil p\xc5\x99\
id\xc3\xa1te zad\xc3\xa1n\xc3\xadm\
 typov\xc3\xa9ho kl\xc3\xad\xc4\
\x8de a v\xc3\xbdrobn\xc3\xadho\
 \xc4\x8d\xc3\xadsla. Komuni\
kace \xe2\x86\x92 Re\xc5\xbeim \
online\x0anav\xc3\xa1\xc5\xbee \
spojen\xc3\xad. Dokume\
nt na\xc4\x8dten\xc3\xbd z j\
in\xc3\xa9ho ventilu (\
jin\xc3\xa9 v\xc3\xbdrobn\xc3\xad \
\xc4\x8d\xc3\xadslo) program\
 nejprve ohl\xc3\xa1s\xc3\
\xad: pokra\xc4\x8dovat s\
 n\xc3\xadm, nebo p\xc5\x99e\
j\xc3\xadt do re\xc5\xbeimu \
offline. Li\xc5\xa1\xc3\xad-\
li se otev\xc5\x99en\xc3\xbd\
 z\xc3\xa1znam paramet\
r\xc5\xaf od ventilu, \
program zobraz\xc3\xad\
 rozd\xc3\xadly a\x0azept\
\xc3\xa1 se, zda p\xc5\x99ev\
z\xc3\xadt hodnoty ven\
tilu, odeslat ho\
dnoty dokumentu \
(na\xc4\x8dten\xc3\xad do ve\
ntilu) nebo\x0azru\xc5\
\xa1it. V re\xc5\xbeimu o\
nline jde ka\xc5\xbed\xc3\
\xa1 zm\xc4\x9bna ihned d\
o ventilu i do d\
okumentu, v re\xc5\xbe\
imu offline\x0apouz\
e do dokumentu. \
P\xc5\x99evezme-li dok\
ument hodnoty ve\
ntilu jin\xc3\xa9ho ty\
pu, stane se nov\
\xc3\xbdm, neulo\xc5\xbeen\xc3\xbd\
m dokumentem (je\
ho soubor si pon\
ech\xc3\xa1, co obsaho\
val); dokument n\
ahran\xc3\xbd do venti\
lu nebo s n\xc3\xadm s\
hodn\xc3\xbd od t\xc3\xa9 do\
by pat\xc5\x99\xc3\xad tomut\
o ventilu (SNV a\
 \xc5\xbe\xc3\xa1dn\xc3\xbd dotaz \
p\xc5\x99i dal\xc5\xa1\xc3\xadm p\xc5\
\x99ipojen\xc3\xad).</p>\x0a\
<p><b>Kdy\xc5\xbe vent\
il vypadne</b> (\
vyta\xc5\xbeen\xc3\xbd kabel\
 USB, vypnut\xc3\xad a\
 zapnut\xc3\xad nap\xc3\xa1j\
en\xc3\xad, CAN bus-of\
f,\x0arestart, po k\
ter\xc3\xa9m se ventil\
 nevr\xc3\xa1t\xc3\xad), pro\
gram p\xc5\x99ejde do \
re\xc5\xbeimu offline,\
 v\xc5\xa1echny hodnot\
y\x0azachov\xc3\xa1 a ven\
til s\xc3\xa1m hled\xc3\xa1:\
 stavov\xc3\xbd \xc5\x99\xc3\xa1de\
k ukazuje <i>Re\xc5\
\xbeim: OBNOVA SPOJ\
EN\xc3\x8d\xe2\x80\xa6 3 s</i>.\
 Hled\xc3\xa1 na\x0astejn\
\xc3\xa9m spojen\xc3\xad \xe2\x80\x94\
 po CAN i pod ji\
n\xc3\xbdm \xc4\x8d\xc3\xadslem uz\
lu, pokud v\xc3\xbdrob\
n\xc3\xad \xc4\x8d\xc3\xadslo (0x1\
018/4) \xc5\x99\xc3\xadk\xc3\xa1, \
\xc5\xbee jde\x0ao tent\xc3\xbd\
\xc5\xbe ventil. A\xc5\xbe s\
e ventil vr\xc3\xa1t\xc3\xad\
, program jej na\
\xc4\x8dte a porovn\xc3\xa1 \
s dokumentem jak\
o p\xc5\x99i\x0ap\xc5\x99echodu\
 do re\xc5\xbeimu onli\
ne (<i>Op\xc4\x9bt onl\
ine</i>, pokud s\
e shoduj\xc3\xad); bez\
 v\xc3\xa1s se do vent\
ilu nic\x0anezap\xc3\xad\xc5\
\xa1e: hodnoty zm\xc4\x9b\
n\xc4\x9bn\xc3\xa9 online, k\
ter\xc3\xa9 ventil p\xc5\x99\
i vypnut\xc3\xad nap\xc3\xa1\
jen\xc3\xad ztratil, j\
sou nab\xc3\xaddnuty\x0av\
 dialogu rozd\xc3\xadl\
\xc5\xaf, ne odesl\xc3\xa1ny\
. Test lad\xc4\x9bn\xc3\xad \
p\xc5\x99eru\xc5\xa1en\xc3\xbd v\xc3\xbd\
padkem spojen\xc3\xad \
zap\xc3\xad\xc5\xa1e zp\xc4\x9bt, \
co\x0azm\xc4\x9bnil, jakm\
ile je ventil zp\
\xc4\x9bt, a ohl\xc3\xa1s\xc3\xad \
to. Osciloskop z\
aznamen\xc3\xa1v\xc3\xa1 d\xc3\xa1\
l; gener\xc3\xa1tor \xc5\xbe\
\xc3\xa1dan\xc3\xa9 hodnoty \
a test\x0alad\xc4\x9bn\xc3\xad \
z\xc5\xafstanou zastav\
eny, dokud je ne\
spust\xc3\xadte (po CA\
N se hl\xc3\xadd\xc3\xa1n\xc3\xad \
p\xc5\x99\xc3\xadjmu, kter\xc3\xa9\
 p\xc5\x99eru\xc5\xa1en\xc3\xbd\x0age\
ner\xc3\xa1tor \xc5\xbe\xc3\xa1dan\
\xc3\xa9 hodnoty nasta\
vil ve ventilu, \
vr\xc3\xa1t\xc3\xad, jakmile\
 je ventil zp\xc4\x9bt\
, a stavov\xc3\xbd \xc5\x99\xc3\
\xa1dek\x0ato ohl\xc3\xa1s\xc3\xad\
). Stav bus-off \
va\xc5\xa1eho CAN adap\
t\xc3\xa9ru stavov\xc3\xbd \xc5\
\x99\xc3\xa1dek uvede; ve\
ntil se znovu na\
jde,\x0ajakmile je \
adapt\xc3\xa9r op\xc4\x9bt n\
a sb\xc4\x9brnici. P\xc5\x99\
eru\xc5\xa1en\xc3\xa9 na\xc4\x8dte\
n\xc3\xad do ventilu o\
hl\xc3\xa1s\xc3\xad, co se\x0as\
talo a co ventil\
 obsahuje; nepok\
ra\xc4\x8duje samo. Ji\
n\xc3\xbd ventil (jin\xc3\
\xa9 v\xc3\xbdrobn\xc3\xad \xc4\x8d\xc3\xad\
slo) na m\xc3\xadst\xc4\x9b\x0a\
ztracen\xc3\xa9ho je n\
ov\xc3\xbd ventil: pro\
gram to ohl\xc3\xa1s\xc3\xad\
 a s\xc3\xa1m se k n\xc4\x9b\
mu nep\xc5\x99ipoj\xc3\xad. \
P\xc5\x99echod do re\xc5\xbe\
imu\x0aonline nebo \
offline hled\xc3\xa1n\xc3\
\xad ukon\xc4\x8d\xc3\xad. U em\
ulovan\xc3\xa9ho venti\
lu to ukazuj\xc3\xad V\
entil \xe2\x86\x92 Emulov\
an\xc3\xbd ventil\x0a\xe2\x86\x92 \
<b>Vyt\xc3\xa1hnout ka\
bel USB</b> a <b\
>Znovu zapojit k\
abel USB</b>.</p\
>\x0a<p>Hodnoty zm\xc4\
\x9bn\xc4\x9bn\xc3\xa9 online j\
sou ve ventilu a\
ktivn\xc3\xad, ale je\xc5\
\xa1t\xc4\x9b neulo\xc5\xbeen\xc3\xa9\
: p\xc5\x99i p\xc5\x99echodu\
 do\x0are\xc5\xbeimu offl\
ine program nab\xc3\
\xaddne jejich ulo\xc5\
\xbeen\xc3\xad a Ventil \xe2\
\x86\x92 <b>Ulo\xc5\xbeit do\
 pam\xc4\x9bti ventilu\
</b> je ulo\xc5\xbe\xc3\xad\x0a\
hned (s \xc4\x8d\xc3\xadm ve\
ntil pracuje, s \
t\xc3\xadm i nastartuj\
e; zaznamen\xc3\xa1 se\
 do historie). <\
b>Na\xc4\x8dten\xc3\xad do v\
entilu</b> zap\xc3\xad\
\xc5\xa1e v\xc5\xa1echny\x0ahod\
noty, p\xc5\x99e\xc4\x8dte j\
e zp\xc4\x9bt, porovn\xc3\
\xa1 a ulo\xc5\xbe\xc3\xad; ulo\
\xc5\xbe\xc3\xad se jen tehd\
y, je-li ka\xc5\xbed\xc3\xa1\
 hodnota ov\xc4\x9b\xc5\x99e\
na.\x0aP\xc5\x99ed prvn\xc3\xad\
m na\xc4\x8dten\xc3\xadm do \
ventilu program \
ulo\xc5\xbe\xc3\xad z\xc3\xa1lohu \
vlastn\xc3\xadch param\
etr\xc5\xaf ventilu do\
 slo\xc5\xbeky\x0au\xc5\xbeivat\
elsk\xc3\xbdch dat (<c\
ode>backups/&lt;\
v\xc3\xbdrobn\xc3\xad \xc4\x8d\xc3\xadsl\
o&gt;/</code>).<\
/p>\x0a<p><b>Restar\
t ventilu</b> a \
<b>Obnoven\xc3\xad tov\
\xc3\xa1rn\xc3\xadho nastave\
n\xc3\xad</b> jsou dov\
oleny pouze p\xc5\x99i\
\x0aodpojen\xc3\xa9m hydr\
aulick\xc3\xa9m obvodu\
; program v\xc3\xa1s p\
o\xc5\xbe\xc3\xa1d\xc3\xa1 o potvr\
zen\xc3\xad.</p>\x0a<p>Ve\
ntil \xe2\x86\x92 <b>Ov\xc4\x9b\
\xc5\x99it restartem\xe2\x80\
\xa6</b> (po na\xc4\x8dte\
n\xc3\xad do ventilu, \
dokud z\xc5\xafst\xc3\xa1v\xc3\xa1\
 online tent\xc3\xbd\xc5\xbe\
\x0aventil) ventil \
po stejn\xc3\xa9m potv\
rzen\xc3\xad odpojen\xc3\xa9\
 hydrauliky rest\
artuje a zp\xc4\x9btn\xc4\
\x9b na\xc4\x8dte jeho\x0apa\
rametry: stavov\xc3\
\xbd \xc5\x99\xc3\xa1dek ohl\xc3\xa1s\
\xc3\xad \xe2\x80\x9e\xe2\x80\xa6 zp\xc4\x9btn\
\xc4\x9b na\xc4\x8dteno beze\
 zm\xc4\x9bny \xe2\x80\xa6: ov\xc4\
\x9b\xc5\x99eno po restar\
tu\xe2\x80\x9c, nebo\x0ahl\xc3\xa1\
\xc5\xa1en\xc3\xad vyjmenuje\
 ka\xc5\xbedou hodnotu\
, kterou si vent\
il neponechal (o\
\xc4\x8dek\xc3\xa1v\xc3\xa1no \xe2\x86\x92 \
na\xc4\x8dteno), a his\
torie\x0av\xc3\xbdsledek \
zaznamen\xc3\xa1. Hl\xc3\xa1\
\xc5\xa1en\xc3\xad o na\xc4\x8dten\
\xc3\xad do ventilu \xc5\x99\
\xc3\xadk\xc3\xa1, jak si ve\
ntil hodnoty pon\
ech\xc3\xa1v\xc3\xa1:\x0a\xe2\x80\x9eulo\
\xc5\xbeeno pomoc\xc3\xad 0x\
1010\xe2\x80\x9c, nebo p\xc5\
\x99es CANopen u ve\
ntilu bez p\xc5\x99\xc3\xadk\
azu k ulo\xc5\xbeen\xc3\xad \
\xe2\x80\x9eventil si hod\
noty\x0aponechal ta\
k, jak byly zaps\
\xc3\xa1ny (nem\xc3\xa1 p\xc5\x99\xc3\
\xadkaz k ulo\xc5\xbeen\xc3\xad\
)\xe2\x80\x9c. Hodnoty zm\
\xc4\x9bn\xc4\x9bn\xc3\xa9 online \
a dosud\x0aneulo\xc5\xbee\
n\xc3\xa9 je t\xc5\x99eba ne\
jprve ulo\xc5\xbeit (r\
estart by je ztr\
atil). Neozve-li\
 se ventil znovu\
, program\x0ap\xc5\x99ejd\
e do re\xc5\xbeimu off\
line a \xc5\x99ekne, c\
o ventil podle v\
\xc5\xa1eho obsahuje; \
dokument si pone\
ch\xc3\xa1 ka\xc5\xbedou\x0ahod\
notu.</p>\x0a\x0a<h2>S\
oubory</h2>\x0a<p>Z\
\xc3\xa1znamy parametr\
\xc5\xaf (<code>*.prm<\
/code>) jsou tex\
tov\xc3\xa9 soubory. O\
tev\xc5\x99\xc3\xadt, Ulo\xc5\xbei\
t, Ulo\xc5\xbeit jako,\
\x0anaposledy otev\xc5\
\x99en\xc3\xa9 soubory a \
p\xc5\x99eta\xc5\xbeen\xc3\xad my\xc5\
\xa1\xc3\xad funguj\xc3\xad obv\
ykl\xc3\xbdm zp\xc5\xafsobem\
; p\xc5\x99ed ztr\xc3\xa1tou\
\x0aneulo\xc5\xbeen\xc3\xbdch z\
m\xc4\x9bn se program \
zept\xc3\xa1. Ka\xc5\xbedou \
zm\xc4\x9bnu lze vr\xc3\xa1t\
it (Ctrl+Z) a zn\
ovu prov\xc3\xa9st\x0a(Ct\
rl+Y). Soubor \xe2\x86\
\x92 Tisk a Soubor \
\xe2\x86\x92 Export do PD\
F vytvo\xc5\x99\xc3\xad prot\
okol parametr\xc5\xaf \
s typov\xc3\xbdm kl\xc3\xad\xc4\
\x8dem,\x0av\xc3\xbdrobn\xc3\xadm \
\xc4\x8d\xc3\xadslem, firmwa\
re, souborem, da\
tem, \xc3\xbarovn\xc3\xad op\
r\xc3\xa1vn\xc4\x9bn\xc3\xad, post\
upov\xc3\xbdm diagrame\
m a v\xc5\xa1emi\x0aparam\
etry s jednotkam\
i. Hodnoty zm\xc4\x9bn\
\xc4\x9bn\xc3\xa9 od ulo\xc5\xbeen\
\xc3\xad souboru jsou \
ozna\xc4\x8deny <b>*</\
b> a \xc5\x99\xc3\xa1dek\x0a\xe2\x80\x9e\
Soubor\xe2\x80\x9c to uv\xc3\
\xa1d\xc3\xad; ka\xc5\xbed\xc3\xa1 st\
rana uv\xc3\xa1d\xc3\xad typ\
ov\xc3\xbd kl\xc3\xad\xc4\x8d a v\xc3\
\xbdrobn\xc3\xad \xc4\x8d\xc3\xadslo \
a sv\xc3\xa9 \xc4\x8d\xc3\xadslo s\
trany; na\x0aposled\
n\xc3\xad stran\xc4\x9b je \xc5\
\x99\xc3\xa1dek pro datum\
, jm\xc3\xa9no a podpi\
s.</p>\x0a<p><b>Z\xc3\xa1\
loha ventilu</b>\
: p\xc5\x99ipojte se (\
re\xc5\xbeim online), \
Ventil \xe2\x86\x92 Sta\xc5\xbe\
en\xc3\xad z ventilu, \
pak\x0aSoubor \xe2\x86\x92 <\
b>Ulo\xc5\xbeit z\xc3\xa1lo\xc5\
\xben\xc3\xad kopii\xe2\x80\xa6</b\
> (navr\xc5\xbeen\xc3\xbd n\xc3\
\xa1zev: typov\xc3\xbd kl\
\xc3\xad\xc4\x8d, v\xc3\xbdrobn\xc3\xad \
\xc4\x8d\xc3\xadslo, datum\x0aa\
 \xc4\x8das). Kopie se\
 zap\xc3\xad\xc5\xa1e a otev\
\xc5\x99en\xc3\xbd dokument \
z\xc5\xafstane, jak\xc3\xbd \
byl: pozd\xc4\x9bj\xc5\xa1\xc3\xad\
 zm\xc4\x9bny se ukl\xc3\xa1\
daj\xc3\xad do\x0ajeho vl\
astn\xc3\xadho souboru\
, nikdy do z\xc3\xa1lo\
hy. Naproti tomu\
 Ulo\xc5\xbeit jako ud\
\xc4\x9bl\xc3\xa1 z nov\xc3\xa9ho \
souboru\x0aotev\xc5\x99en\
\xc3\xbd dokument.</p>\
\x0a\x0a<h2>Kl\xc3\xa1vesnic\
e</h2>\x0a<table>\x0a<\
tr><td>Ctrl+O / \
Ctrl+S / Ctrl+Sh\
ift+S</td><td>Ot\
ev\xc5\x99\xc3\xadt / Ulo\xc5\xbei\
t / Ulo\xc5\xbeit jako\
</td></tr>\x0a<tr><\
td>Ctrl+Z / Ctrl\
+Y</td><td>Zp\xc4\x9bt\
 / Znovu</td></t\
r>\x0a<tr><td>Ctrl+\
P / Ctrl+E</td><\
td>Tisk / Export\
 do PDF</td></tr\
>\x0a<tr><td>Ctrl+1\
 / Ctrl+2 / Ctrl\
+3 / Ctrl+4</td>\
<td>Postupov\xc3\xbd d\
iagram / Seznam \
parametr\xc5\xaf / Osc\
iloskop / Okno C\
ANopen</td></tr>\
\x0a<tr><td>F5 / Sh\
ift+F5</td><td>R\
e\xc5\xbeim online / R\
e\xc5\xbeim offline</t\
d></tr>\x0a<tr><td>\
Ctrl+U / Ctrl+D<\
/td><td>Na\xc4\x8dten\xc3\
\xad do ventilu / S\
ta\xc5\xbeen\xc3\xad z venti\
lu</td></tr>\x0a<tr\
><td>Ctrl+T / Ct\
rl+I / Ctrl+H</t\
d><td>V\xc3\xbdb\xc4\x9br ve\
ntilu / Stav ven\
tilu / Konfigura\
ce HID</td></tr>\
\x0a</table>\x0a<p><b>\
Skripty a zku\xc5\xa1e\
bn\xc3\xad stanice</b>\
: ventil z Pytho\
nu a ze shellov\xc3\
\xbdch skript\xc5\xaf, <a\
 href=\x22scripting\
_en.html\x22>na t\xc3\xa9\
to str\xc3\xa1nce</a> \
(anglicky).</p>\x0a\
</body>\x0a</html>\x0a\
\
\x00\x00\x08^\
<\
!DOCTYPE html>\x0a<\
html lang=\x22cs\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>Historie vent\
ilu</title></hea\
d>\x0a<body>\x0a<p><a \
href=\x22help_cs.ht\
ml\x22>N\xc3\xa1pov\xc4\x9bda p\
rm9tool</a></p>\x0a\
<h1>Historie ven\
tilu</h1>\x0a<p>Ka\xc5\
\xbed\xc3\xa1 operace s p\
arametry ventilu\
 se zaznamen\xc3\xa1 s\
 \xc4\x8dasem (UTC), v\
\xc3\xbdrobn\xc3\xadm \xc4\x8d\xc3\xadsl\
em, typov\xc3\xbdm\x0akl\xc3\
\xad\xc4\x8dem, firmware,\
 p\xc5\x99ipojen\xc3\xadm, v\
erz\xc3\xad programu, \
u\xc5\xbeivatelem a st\
anic\xc3\xad: \xc4\x8dten\xc3\xad,\
 na\xc4\x8dten\xc3\xad do ve\
ntilu\x0a(a k \xc4\x8demu\
), z\xc3\xa1lohy, ulo\xc5\
\xbeen\xc3\xad, tov\xc3\xa1rn\xc3\xad\
 nastaven\xc3\xad, pro\
tokoly o zkou\xc5\xa1c\
e a co jste prov\
edli online\x0a\xe2\x80\x94 \
hodnoty z porovn\
\xc3\xa1van\xc3\xa9ho soubor\
u nebo z histori\
e, p\xc5\x99evzat\xc3\xa9 na\
staven\xc3\xad regulac\
e \xe2\x80\x94 s ka\xc5\xbedou\x0a\
zm\xc4\x9bn\xc4\x9bnou hodno\
tou. Z\xc3\xa1znamy je\
dnoho ventilu tv\
o\xc5\x99\xc3\xad \xc5\x99et\xc4\x9bzec \
hash\xc5\xaf, tak\xc5\xbee z\
m\xc4\x9bn\xc4\x9bn\xc3\xbd z\xc3\xa1zna\
m se\x0aodhal\xc3\xad.</p\
>\x0a<p>Ventil \xe2\x86\x92 \
<b>Historie\xe2\x80\xa6</\
b> vyp\xc3\xad\xc5\xa1e z\xc3\xa1z\
namy p\xc5\x99ipojen\xc3\xa9\
ho ventilu (nebo\
 zadan\xc3\xa9ho v\xc3\xbdro\
bn\xc3\xadho\x0a\xc4\x8d\xc3\xadsla).\
 Sloupec <b>Co b\
ylo provedeno</b\
> uv\xc3\xa1d\xc3\xad v\xc3\xbdzna\
m ka\xc5\xbed\xc3\xa9ho z\xc3\xa1z\
namu, nap\xc5\x99. \xe2\x80\x9e\
Nastaven\xc3\xad\x0aregul\
ace p\xc5\x99evzato, z\
aps\xc3\xa1no online: \
Autotune; POSKP \
0,4 \xe2\x86\x92 0,55\xe2\x80\x9c.\
</p>\x0a<ul>\x0a<li><b\
>Porovnat dva vy\
bran\xc3\xa9 z\xc3\xa1znamy<\
/b>: rozd\xc3\xadl v p\
orovn\xc3\xa1n\xc3\xad; ozna\
\xc4\x8dte hodnoty a p\
\xc5\x99evezm\xc4\x9bte je\x0ad\
o dokumentu nebo\
 je zapi\xc5\xa1te do \
ventilu.</li>\x0a<l\
i><b>Obnovit do \
dokumentu</b>: c\
el\xc3\xa1 sada z\xc3\xa1zna\
mu v\xc4\x8detn\xc4\x9b typo\
v\xc3\xa9ho kl\xc3\xad\xc4\x8de (j\
eden krok zp\xc4\x9bt)\
.\x0a<b>Obnovit do \
ventilu</b>: tra\
nsak\xc4\x8dn\xc3\xad na\xc4\x8dte\
n\xc3\xad do ventilu, \
ze kter\xc3\xa9ho z\xc3\xa1z\
nam poch\xc3\xa1z\xc3\xad (v\
 re\xc5\xbeimu\x0aonline \
s n\xc3\xadm).</li>\x0a<l\
i><b>Exportovat\xe2\
\x80\xa6</b>: z\xc3\xa1znam \
jako <code>*.prm\
</code> nebo CSV\
. <b>Datab\xc3\xa1ze\xe2\x80\
\xa6</b>: SQLite\x0av \
tomto po\xc4\x8d\xc3\xadta\xc4\x8d\
i, nebo server P\
ostgreSQL pro li\
nku se stanicemi\
, a co d\xc4\x9blat, k\
dy\xc5\xbe nen\xc3\xad\x0adostu\
pn\xc3\xa1.</li>\x0a</ul>\
\x0a<p>Zaznamen\xc3\xa1va\
j\xc3\xad se tak\xc3\xa9 b\xc4\x9b\
hy Autotune, fre\
kven\xc4\x8dn\xc3\xad charak\
teristiky, zku\xc5\xa1\
ebn\xc3\xad protokoly \
(s\x0ahodnotami, kt\
er\xc3\xa9 nevyhov\xc4\x9bly\
, a po ulo\xc5\xbeen\xc3\xad\
 s PDF) a restar\
ty ventilu. <b>D\
vojklik</b> na z\
\xc3\xa1znam\x0auk\xc3\xa1\xc5\xbee j\
eho podrobnosti \
\xe2\x80\x94 ka\xc5\xbed\xc3\xa9 pole\
, <b>Otev\xc5\x99\xc3\xadt P\
DF</b>, <b>Porov\
nat s p\xc5\x99edchoz\xc3\
\xadm z\xc3\xa1znamem</b>\
 \xe2\x80\x94\x0anebo p\xc5\x99i d\
vou vybran\xc3\xbdch z\
\xc3\xa1znamech jejich\
 porovn\xc3\xa1n\xc3\xad. Ty\
pov\xc3\xbd kl\xc3\xad\xc4\x8d ven\
tilu se nikdy ne\
m\xc4\x9bn\xc3\xad: z\xc3\xa1znamy\
\x0ajin\xc3\xa9ho typu po\
d stejn\xc3\xbdm v\xc3\xbdro\
bn\xc3\xadm \xc4\x8d\xc3\xadslem (\
emulovan\xc3\xa9 venti\
ly dvou b\xc4\x9bh\xc5\xaf m\
ohou m\xc3\xadt stejn\xc3\
\xa9) jsou\x0aozna\xc4\x8den\
y \xe2\x9a\xa0 a okno to \
uv\xc3\xa1d\xc3\xad.</p>\x0a</b\
ody>\x0a</html>\x0a\
\x00\x00\x1b\x84\
<\
!DOCTYPE html>\x0a<\
html lang=\x22de\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>Einstellung u\
nd Charakterisie\
rung</title></he\
ad>\x0a<body>\x0a<p><a\
 href=\x22help_de.h\
tml\x22>Hilfe zu pr\
m9tool</a></p>\x0a<\
h1>Einstellung u\
nd Charakterisie\
rung</h1>\x0a<p>Das\
 Fenster \xc3\xb6ffnet\
 sich aus dem Os\
zilloskop (<b>Ei\
nstellung und Ch\
arakterisierung\xe2\
\x80\xa6</b>)\x0aoder aus\
 den Reglerbl\xc3\xb6c\
ken des Ablaufdi\
agramms. Online \
bewegt es das ve\
rbundene Ventil,\
 offline\x0al\xc3\xa4uft \
es auf einer emu\
lierten Kopie de\
s Ventils des Do\
kuments. Das Ven\
til muss seinem \
Sollwert\x0afolgen \
(ein -CA-Ventil:\
 zuerst NMT Star\
t und Freigeben)\
; ein Test biete\
t die Freigabe a\
n.</p>\x0a<p><b>Ach\
tung:</b> Jeder \
Test bewegt den \
Schieber (an ein\
em E04 auch den \
Antrieb). Stelle\
n Sie\x0asicher, da\
ss sich die Masc\
hine bewegen dar\
f. <b>Stopp</b> \
beendet einen Te\
st sofort und st\
ellt\x0adas Ventil \
wieder her, wie \
es war.</p>\x0a\x0a<h2\
>Der Regelkreis<\
/h2>\x0a<p><b>Regel\
kreis</b> w\xc3\xa4hlt\
, worauf die Tes\
ts wirken. <b>La\
geregler (Schieb\
er)</b>: der Sol\
lwert\x0aist die Sc\
hieberlage (Rege\
lungsart 2, CTRL\
MODE). <b>Prozes\
sregler (E04)</b\
>: der Sollwert\x0a\
ist der Prozessw\
ert des externen\
 Sensors, den de\
r Prozessregler \
\xc3\xbcber Schieber u\
nd Antrieb\x0aschli\
e\xc3\x9ft (Regelungsa\
rt 4, die Vorein\
stellung des E04\
). Ein E04 in Re\
gelungsart 4 \xc3\xb6f\
fnet auf dem\x0aPro\
zessregelkreis; \
der Lageregelkre\
is braucht Regel\
ungsart 2, einge\
stellt, solange \
das Ventil\x0anicht\
 freigegeben ist\
.</p>\x0a\x0a<h2>E04: \
den Prozessregel\
kreis einstellen\
</h2>\x0a<ol>\x0a<li>Z\
uerst den extern\
en Sensor einric\
hten (die Parame\
ter \xe2\x80\x9eExterner \
Sensor\xe2\x80\x9c: Signa\
ltyp\x0aSENSTYPE, P\
olarit\xc3\xa4t, Verst\
\xc3\xa4rkung und Offs\
et), so dass der\
 Prozess-Istwert\
 dem Antrieb \xc3\xbcb\
er\x0aseinen Bereic\
h in der richtig\
en Richtung folg\
t. Im Oszillosko\
p pr\xc3\xbcfen (Proze\
ss-Istwert),\x0aw\xc3\xa4\
hrend sich der A\
ntrieb langsam b\
ewegt.</li>\x0a<li>\
Die Regelungsart\
 auf 4 lassen un\
d <b>Prozessregl\
er (E04)</b> w\xc3\xa4\
hlen.</li>\x0a<li>D\
er Antrieb integ\
riert: seine Pos\
ition \xc3\xa4ndert si\
ch, solange der \
Schieber offen i\
st. Die\x0aVorgaben\
 des Autotune fo\
lgen dem Regelkr\
eis: ein Sprung \
von 20 % und ein\
e Ziel-Ausregelz\
eit von\x0a500 ms (\
die 40 ms des Sc\
hiebers erreicht\
 kein Antrieb). \
F\xc3\xbcr einen langs\
amen oder schwer\
en\x0aAntrieb das Z\
iel erh\xc3\xb6hen.</l\
i>\x0a<li>Autotune \
starten, den Vor\
schlag pr\xc3\xbcfen (\
die Spr\xc3\xbcnge des\
 Profils in beid\
e Richtungen und\
\x0aseine statische\
 Pr\xc3\xbcfung), \xc3\xbcbe\
rnehmen, dann Ve\
ntil \xe2\x86\x92 Im Vent\
il speichern.</l\
i>\x0a<li>Bei einem\
 Schieber mit \xc3\x9c\
berdeckung misst\
 die Seite <b>Du\
rchflusskennlini\
e (E04)</b> die\x0a\
Totzone und schl\
\xc3\xa4gt OFFSETPOS/O\
FFSETNEG f\xc3\xbcr de\
n Prozessregelkr\
eis vor.</li>\x0a</\
ol>\x0a\x0a<h2>Berecht\
igungsstufe und \
Fehler</h2>\x0a<p>R\
eglerverst\xc3\xa4rkun\
gen, Linearisier\
ungen und Offset\
s lassen sich nu\
r auf der Stufe\x0a\
<b>Experte</b> \xc3\
\xa4ndern (Ansicht \
\xe2\x86\x92 Berechtigung\
sstufe). Ein Tes\
t, dessen Ergebn\
is auf der\x0ajetzi\
gen Stufe nicht \
\xc3\xbcbernommen werd\
en k\xc3\xb6nnte, frag\
t vor dem Start;\
 sein Ergebnis b\
leibt auf der\x0aSe\
ite, so dass Sie\
 danach zu Exper\
te wechseln und \
es \xc3\xbcbernehmen k\
\xc3\xb6nnen, ohne den\
 Test zu\x0awiederh\
olen.</p>\x0a<p>Ein\
 Ventil, das ein\
en Fehler h\xc3\xa4lt \
(FAULT_HOLD, FAU\
LT), folgt seine\
m Sollwert nicht\
: der Test\x0awird \
vor dem Start ab\
gelehnt, und die\
 Statuszeile sag\
t warum. Um FAUL\
T_HOLD zu verlas\
sen, die\x0aUrsache\
 beseitigen (Ven\
til \xe2\x86\x92 Ventilst\
atus zeigt den a\
ktiven Fehler) u\
nd dort <b>Freig\
eben</b>\x0adr\xc3\xbccke\
n: sein erstes S\
teuerwort 08h is\
t das Fehler-R\xc3\xbc\
cksetzen (Handbu\
ch Tabellen 7-19\
 und\x0a7-20, \xc3\x9cber\
gang 10), 09h \xe2\x86\
\x92 0Bh \xe2\x86\x92 0Fh ge\
ben das Ventil w\
ieder frei. Ein \
Ventil ohne CANo\
pen\x0averl\xc3\xa4sst ei\
nen Fehler mit V\
entil \xe2\x86\x92 Ventil\
 neu starten.</p\
>\x0a\x0a<h2>Die Seite\
n</h2>\x0a<ul>\x0a<li>\
<b>Autotune</b>:\
 modellbasiert (\
einige Spr\xc3\xbcnge,\
 ein angepasstes\
 Modell, Verst\xc3\xa4\
rkungen, die\x0anic\
ht schwingen) od\
er nach der Rege\
l der kritischen\
 Verst\xc3\xa4rkung. D\
er Vorschlag wir\
d neben den\x0ajetz\
igen Verst\xc3\xa4rkun\
gen gezeigt; <b>\
Vorgeschlagene V\
erst\xc3\xa4rkungen \xc3\xbc\
bernehmen</b> se\
tzt sie ins\x0aDoku\
ment (ein R\xc3\xbcckg\
\xc3\xa4ngig-Schritt; \
online auch ins \
Ventil, mit Eint\
rag im Verlauf).\
\x0aDauerhaft speic\
hern mit Ventil \
\xe2\x86\x92 Im Ventil sp\
eichern.</li>\x0a<l\
i><b>Frequenzgan\
g</b>: ein Sinus\
-Sweep um einen \
Arbeitspunkt; di\
e Frequenzen bei\
 \xe2\x88\x923 dB und\x0a\xe2\x88\x92\
90\xc2\xb0 (der Bereic\
h folgt dem Rege\
lkreis: 1 \xe2\x80\xa6 20\
0 Hz f\xc3\xbcr den Sc\
hieber, 0,2 \xe2\x80\xa6 \
20 Hz f\xc3\xbcr den\x0aP\
rozessregelkreis\
).</li>\x0a<li><b>S\
tatische Kennlin\
ie</b>: ein lang\
sames Dreieck; H\
ysterese, Linear\
it\xc3\xa4t und Totzon\
e sowie\x0aein Vors\
chlag f\xc3\xbcr die L\
inearisierung.</\
li>\x0a<li><b>Pr\xc3\xbcf\
bericht</b>: ein\
 Abnahmeprofil (\
Spr\xc3\xbcnge, Sweep,\
 statische Pr\xc3\xbcf\
ung und ihre Gre\
nzen)\x0ain einem D\
urchlauf; der Be\
richt nennt den \
gepr\xc3\xbcften Regel\
kreis, das PDF n\
ennt auf jeder S\
eite\x0aTypschl\xc3\xbcss\
el und Seriennum\
mer und f\xc3\xbchrt d\
en Parametersatz\
 in Anzeigeeinhe\
iten auf; die\x0aMe\
ssdaten gehen da\
neben in CSV-Dat\
eien. Sprungkenn\
werte werden geg\
en den Sollwert \
gemessen: ein\x0aSp\
rung, der ihn ni\
cht erreicht hat\
, ist \xe2\x80\x9enicht e\
rreicht\xe2\x80\x9c und b\
esteht nicht.</l\
i>\x0a<li><b>Geburt\
surkunde</b> (on\
line): <b>Mit Ge\
burtsurkunde ver\
gleichen</b> spi\
elt eine kurze\x0aF\
eldsignatur (ein\
 kleiner und ein\
 gro\xc3\x9fer Sprung \
in jede Richtung\
, ein kurzer Swe\
ep um die\x0aBandbr\
eite des Ventils\
, eine Hysterese\
schleife; h\xc3\xb6chs\
tens 20 s Bewegu\
ng) und vergleic\
ht jeden\x0aKennwer\
t mit der Endpr\xc3\
\xbcfung des Ventil\
s, die der Verla\
uf zu seiner Ser\
iennummer aufbew\
ahrt:\x0aheute, dam\
als, die \xc3\x84nderu\
ng und die Drift\
grenze (der Teil\
 <code>[drift]</\
code> des Profil\
s, z. B.\x0a<code>b\
ode_phase90_hz =\
 { relative = 15\
 }</code>) und o\
b er gedriftet i\
st; die heutigen\
 Spr\xc3\xbcnge\x0aund de\
r Frequenzgang w\
erden \xc3\xbcber die \
der Geburtsurkun\
de gezeichnet, <\
b>PDF speichern\xe2\
\x80\xa6</b>\x0aschreibt \
den Driftbericht\
. Ohne Endpr\xc3\xbcfu\
ng im Verlauf sa\
gt sie, wie man \
eine erstellt,\x0au\
nd bewegt nichts\
 (Befehlszeile: \
<code>prm9tool -\
-signature --dev\
ice ID --report \
drift.pdf</code>\
).</li>\x0a</ul>\x0a\x0a<\
h2>Das Abnahmepr\
ofil (TOML)</h2>\
\x0a<p>Leer: das ei\
ngebaute Profil.\
 Eine Datei setz\
t, was davon abw\
eicht; jeder Sch\
l\xc3\xbcssel darf\x0afeh\
len. <code>[test\
]</code> und <co\
de>[limits]</cod\
e> gelten f\xc3\xbcr d\
en Lageregelkrei\
s,\x0a<code>[proces\
s.test]</code> u\
nd <code>[proces\
s.limits]</code>\
 f\xc3\xbcr den Prozes\
sregelkreis des\x0a\
E04, dessen eige\
ne Vorgaben Spru\
ngfenster von 1,\
5 s, ein Sweep v\
on 0,2 bis 20 Hz\
,\x0aAnstiegszeit \xe2\
\x89\xa4 0,4 s, Ausreg\
elzeit \xe2\x89\xa4 0,8 s\
 und \xe2\x88\x923 dB \xe2\x89\xa5\
 0,8 Hz sind. Ei\
ne Grenze ist\x0a<c\
ode>{ min = \xe2\x80\xa6 \
}</code>, <code>\
{ max = \xe2\x80\xa6 }</c\
ode> oder beides\
; Zahlen in der \
Datei mit\x0aDezima\
lpunkt.</p>\x0a<pre\
>\x0aname = \x22PRM9-0\
6 Endpr\xc3\xbcfung\x22\x0a[\
test]\x0astep_ampli\
tudes_pct = [5, \
25, 90]\x0astep_dur\
ation_s = 0.15\x0as\
tatic_period_s =\
 20\x0a[limits]\x0aste\
p_overshoot_pct \
= { max = 15 }\x0as\
tep_rise_s = { m\
ax = 0.03 }\x0abode\
_bandwidth_hz = \
{ min = 15 }\x0asta\
tic_hysteresis_p\
ct = { max = 2 }\
\x0a\x0a[process.test]\
      # E04 in R\
egelungsart 4\x0ast\
ep_duration_s = \
2.0\x0a[process.lim\
its]\x0astep_rise_s\
 = { max = 0.5 }\
\x0astep_settling_s\
 = { max = 1.0 }\
\x0aflow_gain = { m\
in = 3 }\x0a</pre>\x0a\
<p>Kennwerte: st\
ep_overshoot_pct\
, step_rise_s, s\
tep_settling_s, \
bode_bandwidth_h\
z,\x0abode_phase90_\
hz, static_gain,\
 static_hysteres\
is_pct, static_l\
inearity_pct,\x0ast\
atic_dead_band_p\
ct, flow_gain, f\
low_dead_band_pc\
t. Ein unbekannt\
er Schl\xc3\xbcssel od\
er ein falscher\x0a\
Wert wird mit Da\
tei und Schl\xc3\xbcss\
el abgelehnt.</p\
>\x0a<p>Die Karte <\
b>Sprungantwort<\
/b> des Oszillos\
kops misst \xc3\x9cber\
schwingen, Ansti\
egs- und\x0aAusrege\
lzeit jedes geze\
igten Sprungs.</\
p>\x0a</body>\x0a</htm\
l>\x0a\
\x00\x00\x06\x87\
<\
!DOCTYPE html>\x0a<\
html lang=\x22cs\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>Porovn\xc3\xa1n\xc3\xad s\
ad parametr\xc5\xaf</t\
itle></head>\x0a<bo\
dy>\x0a<p><a href=\x22\
help_cs.html\x22>N\xc3\
\xa1pov\xc4\x9bda prm9too\
l</a></p>\x0a<h1>Po\
rovn\xc3\xa1n\xc3\xad sad pa\
rametr\xc5\xaf</h1>\x0a<p\
>Porovn\xc3\xa1n\xc3\xad uka\
zuje dv\xc4\x9b sady p\
arametr\xc5\xaf vedle \
sebe v zobrazova\
n\xc3\xbdch jednotk\xc3\xa1c\
h a jako t\xc5\x99et\xc3\xad\
\x0asloupec tov\xc3\xa1rn\
\xc3\xad nastaven\xc3\xad. T\
u\xc4\x8dn\xc3\xa9 hodnoty s\
e li\xc5\xa1\xc3\xad.</p>\x0a<u\
l>\x0a<li>Soubor \xe2\x86\
\x92 <b>Porovnat se\
 souborem\xe2\x80\xa6</b>\
: dokument proti\
 souboru <code>*\
.prm</code> (dia\
log\x0aotev\xc5\x99e napo\
sledy pou\xc5\xbeitou \
slo\xc5\xbeku).</li>\x0a<\
li>Ventil \xe2\x86\x92 <b\
>Porovnat s vent\
ilem</b> (online\
): dokument prot\
i tomu, co venti\
l pr\xc3\xa1v\xc4\x9b\x0aobsahu\
je.</li>\x0a<li>P\xc5\x99\
i p\xc5\x99echodu do r\
e\xc5\xbeimu online s \
odli\xc5\xa1n\xc3\xbdm dokum\
entem: <b>Zvolit\
 po parametrech\xe2\
\x80\xa6</b>.</li>\x0a<li\
>Ventil \xe2\x86\x92 Hist\
orie: vyberte dv\
a z\xc3\xa1znamy, <b>P\
orovnat dva vybr\
an\xc3\xa9 z\xc3\xa1znamy</b\
>.</li>\x0a</ul>\x0a<h\
2>Vr\xc3\xa1cen\xc3\xad hodn\
ot</h2>\x0a<ol>\x0a<li\
>V ka\xc5\xbed\xc3\xa9m \xc5\x99\xc3\xa1\
dku ozna\xc4\x8dte po\xc5\
\xbeadovanou hodnot\
u (ve sloupci st\
rany, ze kter\xc3\xa9 \
poch\xc3\xa1z\xc3\xad), nebo\
\x0apro zobrazen\xc3\xa9 \
\xc5\x99\xc3\xa1dky pou\xc5\xbeijt\
e <b>Ozna\xc4\x8dit v\xc5\
\xa1echny zobrazen\xc3\
\xa9 hodnoty \xe2\x80\xa6</b\
>.</li>\x0a<li>Stis\
kn\xc4\x9bte tla\xc4\x8d\xc3\xadtk\
o, kter\xc3\xa9 \xc5\x99\xc3\xadk\xc3\
\xa1, kam hodnoty j\
dou: <b>Zapsat \xe2\
\x80\xa6 ozna\xc4\x8den\xc3\xbdch \
hodnot do\x0aventil\
u</b> (na\xc4\x8dten\xc3\xad\
 p\xc5\x99esn\xc4\x9b t\xc4\x9bcht\
o hodnot do vent\
ilu: z\xc3\xa1pis, zp\xc4\
\x9btn\xc3\xa9 \xc4\x8dten\xc3\xad, p\
orovn\xc3\xa1n\xc3\xad,\x0aulo\xc5\
\xbeen\xc3\xad) nebo <b>P\
\xc5\x99evz\xc3\xadt \xe2\x80\xa6 ozn\
a\xc4\x8den\xc3\xbdch hodnot\
 do dokumentu</b\
> (jeden krok zp\
\xc4\x9bt). \xc5\x98\xc3\xa1dek na\
d\x0atabulkou \xc5\x99\xc3\xadk\
\xc3\xa1, kter\xc3\xbd sloup\
ec pat\xc5\x99\xc3\xad ke kt\
er\xc3\xa9mu tla\xc4\x8d\xc3\xadtk\
u; tla\xc4\x8d\xc3\xadtko z\xc5\
\xafstane \xc5\xa1ed\xc3\xa9, d\
okud nen\xc3\xad nic\x0ao\
zna\xc4\x8deno.</li>\x0a<\
/ol>\x0a<p>Filtry: \
jen rozd\xc3\xadly, je\
den blok postupo\
v\xc3\xa9ho diagramu, \
z\xc3\xa1kladn\xc3\xad nebo \
expertn\xc3\xad \xc3\xbarove\
\xc5\x88.\x0aParametry, k\
ter\xc3\xa9 jedna vari\
anta ventilu nem\
\xc3\xa1, se zobraz\xc3\xad \
jako \xe2\x80\x9e\xe2\x80\x94\xe2\x80\x9c a\
 nelze je zvolit\
.</p>\x0a</body>\x0a</\
html>\x0a\
\x00\x00\x1ad\
<\
!DOCTYPE html>\x0a<\
html lang=\x22cs\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>Lad\xc4\x9bn\xc3\xad a ch\
arakterizace</ti\
tle></head>\x0a<bod\
y>\x0a<p><a href=\x22h\
elp_cs.html\x22>N\xc3\xa1\
pov\xc4\x9bda prm9tool\
</a></p>\x0a<h1>Lad\
\xc4\x9bn\xc3\xad a charakte\
rizace</h1>\x0a<p>O\
kno se otev\xc5\x99e z\
 osciloskopu (<b\
>Lad\xc4\x9bn\xc3\xad a char\
akterizace\xe2\x80\xa6</b\
>) nebo z blok\xc5\xaf\
 regul\xc3\xa1tor\xc5\xaf\x0av \
postupov\xc3\xa9m diag\
ramu. V re\xc5\xbeimu \
online pohybuje \
p\xc5\x99ipojen\xc3\xbdm ven\
tilem, offline b\
\xc4\x9b\xc5\xbe\xc3\xad na emulov\
an\xc3\xa9\x0akopii venti\
lu dokumentu. Ve\
ntil mus\xc3\xad sledo\
vat \xc5\xbe\xc3\xa1danou ho\
dnotu (ventil -C\
A: nejprve NMT s\
tart a\x0aUvolnit);\
 zkou\xc5\xa1ka uvoln\xc4\
\x9bn\xc3\xad nab\xc3\xaddne.</\
p>\x0a<p><b>Pozor:<\
/b> ka\xc5\xbed\xc3\xa1 zkou\
\xc5\xa1ka pohybuje \xc5\xa1\
oup\xc3\xa1tkem (u E04\
 i pohonem). Uji\
st\xc4\x9bte se, \xc5\xbee s\
e stroj\x0asm\xc3\xad poh\
ybovat. <b>Stop<\
/b> zkou\xc5\xa1ku oka\
m\xc5\xbeit\xc4\x9b ukon\xc4\x8d\xc3\xad\
 a vr\xc3\xa1t\xc3\xad venti\
l do p\xc5\xafvodn\xc3\xadho\
 stavu.</p>\x0a\x0a<h2\
>Regula\xc4\x8dn\xc3\xad smy\
\xc4\x8dka</h2>\x0a<p><b>\
Regula\xc4\x8dn\xc3\xad smy\xc4\
\x8dka</b> vol\xc3\xad, n\
a co zkou\xc5\xa1ky p\xc5\
\xafsob\xc3\xad. <b>Regul\
\xc3\xa1tor polohy (\xc5\xa1\
oup\xc3\xa1tko)</b>:\x0a\xc5\
\xbe\xc3\xa1dan\xc3\xa1 hodnota\
 je poloha \xc5\xa1oup\
\xc3\xa1tka (re\xc5\xbeim re\
gulace 2, CTRLMO\
DE). <b>Procesn\xc3\
\xad regul\xc3\xa1tor\x0a(E0\
4)</b>: \xc5\xbe\xc3\xa1dan\xc3\
\xa1 hodnota je pro\
cesn\xc3\xad veli\xc4\x8dina\
 extern\xc3\xadho sn\xc3\xad\
ma\xc4\x8de, kterou pr\
ocesn\xc3\xad regul\xc3\xa1t\
or\x0auzav\xc3\xadr\xc3\xa1 p\xc5\x99\
es \xc5\xa1oup\xc3\xa1tko a \
pohon (re\xc5\xbeim re\
gulace 4, v\xc3\xbdcho\
z\xc3\xad u E04). E04 \
v re\xc5\xbeimu regula\
ce 4 se\x0aotev\xc5\x99e \
na procesn\xc3\xad smy\
\xc4\x8dce; smy\xc4\x8dka po\
lohy pot\xc5\x99ebuje \
re\xc5\xbeim regulace \
2, nastaven\xc3\xbd, d\
okud ventil\x0anen\xc3\
\xad uvoln\xc4\x9bn.</p>\x0a\
\x0a<h2>E04: lad\xc4\x9bn\
\xc3\xad procesn\xc3\xad smy\
\xc4\x8dky</h2>\x0a<ol>\x0a<\
li>Nejprve nasta\
vte extern\xc3\xad sn\xc3\
\xadma\xc4\x8d (parametry\
 \xe2\x80\x9eExtern\xc3\xad sn\xc3\
\xadma\xc4\x8d\xe2\x80\x9c: typ si\
gn\xc3\xa1lu SENSTYPE,\
\x0apolarita, zes\xc3\xad\
len\xc3\xad a posunut\xc3\
\xad), aby skute\xc4\x8dn\
\xc3\xa1 hodnota proce\
su sledovala poh\
on v cel\xc3\xa9m rozs\
ahu\x0aa ve spr\xc3\xa1vn\
\xc3\xa9m sm\xc4\x9bru. Ov\xc4\x9b\
\xc5\x99te to na oscil\
oskopu (skute\xc4\x8dn\
\xc3\xa1 hodnota proce\
su), zat\xc3\xadmco se\
 pohon\x0apomalu po\
hybuje.</li>\x0a<li\
>Ponechte re\xc5\xbeim\
 regulace 4 a zv\
olte <b>Procesn\xc3\
\xad regul\xc3\xa1tor (E0\
4)</b>.</li>\x0a<li\
>Pohon integruje\
: jeho poloha se\
 m\xc4\x9bn\xc3\xad, dokud j\
e \xc5\xa1oup\xc3\xa1tko ote\
v\xc5\x99en\xc3\xa9. V\xc3\xbdchoz\
\xc3\xad hodnoty\x0aautot\
une se \xc5\x99\xc3\xadd\xc3\xad s\
my\xc4\x8dkou: skok 20\
 % a c\xc3\xadlov\xc3\xa1 do\
ba ust\xc3\xa1len\xc3\xad 50\
0 ms (40 ms \xc5\xa1ou\
p\xc3\xa1tka \xc5\xbe\xc3\xa1dn\xc3\xbd \
pohon\x0anedos\xc3\xa1hne\
). Pro pomal\xc3\xbd n\
ebo t\xc4\x9b\xc5\xbek\xc3\xbd poh\
on c\xc3\xadl zvy\xc5\xa1te.\
</li>\x0a<li>Spus\xc5\xa5\
te autotune, zko\
ntrolujte n\xc3\xa1vrh\
 (skoky profilu \
v obou sm\xc4\x9brech \
a jeho statickou\
\x0azkou\xc5\xa1ku), p\xc5\x99e\
vezm\xc4\x9bte jej a p\
ak Ventil \xe2\x86\x92 Ul\
o\xc5\xbeit do pam\xc4\x9bti\
 ventilu.</li>\x0a<\
li>U \xc5\xa1oup\xc3\xa1tka \
s p\xc5\x99ekryt\xc3\xadm zm\
\xc4\x9b\xc5\x99\xc3\xad str\xc3\xa1nka \
<b>Pr\xc5\xaftokov\xc3\xa1 c\
harakteristika (\
E04)</b> p\xc3\xa1smo\x0a\
necitlivosti a n\
avrhne OFFSETPOS\
/OFFSETNEG pro p\
rocesn\xc3\xad smy\xc4\x8dku\
.</li>\x0a</ol>\x0a\x0a<h\
2>\xc3\x9arove\xc5\x88 opr\xc3\xa1\
vn\xc4\x9bn\xc3\xad a poruch\
y</h2>\x0a<p>Konsta\
nty regul\xc3\xa1tor\xc5\xaf\
, linearizace a \
posunut\xc3\xad lze m\xc4\
\x9bnit jen na \xc3\xbaro\
vni <b>Expert</b\
>\x0a(N\xc3\xa1hled \xe2\x86\x92 \xc3\
\x9arove\xc5\x88 opr\xc3\xa1vn\xc4\
\x9bn\xc3\xad). Zkou\xc5\xa1ka,\
 jej\xc3\xad\xc5\xbe v\xc3\xbdsled\
ek by na sou\xc4\x8das\
n\xc3\xa9 \xc3\xbarovni ne\xc5\xa1\
lo p\xc5\x99evz\xc3\xadt, se\
\x0ap\xc5\x99ed spu\xc5\xa1t\xc4\x9bn\
\xc3\xadm zept\xc3\xa1; jej\xc3\
\xad v\xc3\xbdsledek z\xc5\xafs\
tane na str\xc3\xa1nce\
, tak\xc5\xbee m\xc5\xaf\xc5\xbeet\
e p\xc5\x99epnout na E\
xpert\x0adodate\xc4\x8dn\xc4\
\x9b a p\xc5\x99evz\xc3\xadt je\
j bez opakov\xc3\xa1n\xc3\
\xad zkou\xc5\xa1ky.</p>\x0a\
<p>Ventil, kter\xc3\
\xbd dr\xc5\xbe\xc3\xad poruchu\
 (FAULT_HOLD, FA\
ULT), nesleduje \
\xc5\xbe\xc3\xa1danou hodnot\
u: zkou\xc5\xa1ka je\x0ao\
dm\xc3\xadtnuta p\xc5\x99ed \
spu\xc5\xa1t\xc4\x9bn\xc3\xadm a s\
tavov\xc3\xbd \xc5\x99\xc3\xa1dek \
\xc5\x99ekne pro\xc4\x8d. Pr\
o opu\xc5\xa1t\xc4\x9bn\xc3\xad FA\
ULT_HOLD odstra\xc5\
\x88te p\xc5\x99\xc3\xad\xc4\x8dinu\x0a(\
Ventil \xe2\x86\x92 Stav \
ventilu uk\xc3\xa1\xc5\xbee \
aktivn\xc3\xad chybu) \
a tam stiskn\xc4\x9bte\
 <b>Uvolnit</b>:\
 jeho prvn\xc3\xad \xc5\x99\xc3\
\xaddic\xc3\xad\x0aslovo 08h\
 je reset poruch\
y (p\xc5\x99\xc3\xadru\xc4\x8dka, \
tabulky 7-19 a 7\
-20, p\xc5\x99echod 10\
), 09h \xe2\x86\x92 0Bh \xe2\
\x86\x92 0Fh ventil\x0azn\
ovu uvoln\xc3\xad. Ven\
til bez CANopen \
opust\xc3\xad poruchu \
p\xc5\x99\xc3\xadkazem Venti\
l \xe2\x86\x92 Restart ve\
ntilu.</p>\x0a\x0a<h2>\
Str\xc3\xa1nky</h2>\x0a<u\
l>\x0a<li><b>Autotu\
ne</b>: podle mo\
delu (n\xc4\x9bkolik s\
kok\xc5\xaf, p\xc5\x99izp\xc5\xafs\
oben\xc3\xbd model, ko\
nstanty, kter\xc3\xa9\x0a\
nekmitaj\xc3\xad) nebo\
 podle pravidla \
kritick\xc3\xa9ho zes\xc3\
\xadlen\xc3\xad. N\xc3\xa1vrh s\
e zobraz\xc3\xad vedle\
 sou\xc4\x8dasn\xc3\xbdch\x0ako\
nstant; <b>P\xc5\x99ev\
z\xc3\xadt navr\xc5\xbeen\xc3\xa9 \
konstanty</b> je\
 vlo\xc5\xbe\xc3\xad do doku\
mentu (jeden kro\
k zp\xc4\x9bt; online\x0a\
i do ventilu, se\
 z\xc3\xa1znamem v his\
torii). Trvale j\
e ulo\xc5\xbete p\xc5\x99\xc3\xadk\
azem Ventil \xe2\x86\x92 \
Ulo\xc5\xbeit do pam\xc4\x9b\
ti\x0aventilu.</li>\
\x0a<li><b>Frekven\xc4\
\x8dn\xc3\xad charakteris\
tika</b>: sinuso\
v\xc3\xbd rozm\xc3\xadtan\xc3\xbd \
sign\xc3\xa1l kolem pr\
acovn\xc3\xadho bodu;\x0a\
frekvence p\xc5\x99i \xe2\
\x88\x923 dB a \xe2\x88\x9290\xc2\xb0\
 (rozsah se \xc5\x99\xc3\xad\
d\xc3\xad smy\xc4\x8dkou: 1 \
\xe2\x80\xa6 200 Hz pro \xc5\
\xa1oup\xc3\xa1tko, 0,2 \xe2\
\x80\xa6 20 Hz pro\x0apro\
cesn\xc3\xad smy\xc4\x8dku).\
</li>\x0a<li><b>Sta\
tick\xc3\xa1 charakter\
istika</b>: poma\
l\xc3\xbd troj\xc3\xbaheln\xc3\xad\
k; hystereze, li\
nearita a p\xc3\xa1smo\
\x0anecitlivosti a \
n\xc3\xa1vrh lineariza\
ce.</li>\x0a<li><b>\
Protokol o zkou\xc5\
\xa1ce</b>: p\xc5\x99ej\xc3\xad\
mac\xc3\xad profil (sk\
oky, rozm\xc3\xadt\xc3\xa1n\xc3\
\xad, statick\xc3\xa1 zko\
u\xc5\xa1ka a jejich\x0am\
eze) v jednom b\xc4\
\x9bhu; protokol uv\
\xc3\xa1d\xc3\xad zkou\xc5\xa1enou\
 smy\xc4\x8dku, PDF uv\
\xc3\xa1d\xc3\xad na ka\xc5\xbed\xc3\xa9\
 stran\xc4\x9b typov\xc3\xbd\
 kl\xc3\xad\xc4\x8d\x0aa v\xc3\xbdrob\
n\xc3\xad \xc4\x8d\xc3\xadslo a ob\
sahuje sadu para\
metr\xc5\xaf v zobrazo\
van\xc3\xbdch jednotk\xc3\
\xa1ch; nam\xc4\x9b\xc5\x99en\xc3\xa1\
 data jdou vedle\
\x0ado CSV. Hodnoty\
 skok\xc5\xaf se m\xc4\x9b\xc5\x99\
\xc3\xad v\xc5\xaf\xc4\x8di \xc5\xbe\xc3\xa1da\
n\xc3\xa9 hodnot\xc4\x9b: sk\
ok, kter\xc3\xbd ji ne\
dos\xc3\xa1hl, je \xe2\x80\x9en\
edosa\xc5\xbeeno\xe2\x80\x9c\x0aa \
nevyhovuje.</li>\
\x0a<li><b>Rodn\xc3\xbd l\
ist</b> (online)\
: <b>Porovnat s \
rodn\xc3\xbdm listem</\
b> p\xc5\x99ehraje kr\xc3\
\xa1tk\xc3\xbd poln\xc3\xad pod\
pis\x0a(mal\xc3\xbd a vel\
k\xc3\xbd skok v obou \
sm\xc4\x9brech, kr\xc3\xa1tk\
\xc3\xa9 rozm\xc3\xadt\xc3\xa1n\xc3\xad \
kolem \xc5\xa1\xc3\xad\xc5\x99ky p\
\xc3\xa1sma ventilu, h\
ysterezn\xc3\xad\x0asmy\xc4\x8d\
ka; nejv\xc3\xbd\xc5\xa1e 20\
 s pohybu) a por\
ovn\xc3\xa1 ka\xc5\xbed\xc3\xbd uk\
azatel s v\xc3\xbdstup\
n\xc3\xad zkou\xc5\xa1kou ve\
ntilu ulo\xc5\xbeenou\x0a\
v historii k jeh\
o v\xc3\xbdrobn\xc3\xadmu \xc4\x8d\
\xc3\xadslu: dnes, teh\
dy, zm\xc4\x9bna a mez\
 driftu (\xc4\x8d\xc3\xa1st\x0a\
<code>[drift]</c\
ode> profilu, na\
p\xc5\x99. <code>bode_\
phase90_hz = { r\
elative = 15 }</\
code>) a zda\x0ase \
posunul; dne\xc5\xa1n\xc3\
\xad skoky a frekve\
n\xc4\x8dn\xc3\xad charakter\
istika se kresl\xc3\
\xad p\xc5\x99es ty z rod\
n\xc3\xa9ho listu,\x0a<b>\
Ulo\xc5\xbeit PDF\xe2\x80\xa6</\
b> zap\xc3\xad\xc5\xa1e prot\
okol o driftu. B\
ez v\xc3\xbdstupn\xc3\xad zk\
ou\xc5\xa1ky v histori\
i \xc5\x99ekne, jak ji\
\x0avytvo\xc5\x99it, a ni\
c nepohne (p\xc5\x99\xc3\xad\
kazov\xc3\xbd \xc5\x99\xc3\xa1dek:\
\x0a<code>prm9tool \
--signature --de\
vice ID --report\
 drift.pdf</code\
>).</li>\x0a</ul>\x0a\x0a\
<h2>P\xc5\x99ej\xc3\xadmac\xc3\xad\
 profil (TOML)</\
h2>\x0a<p>Pr\xc3\xa1zdn\xc3\xa9\
: vestav\xc4\x9bn\xc3\xbd pr\
ofil. Soubor nas\
tav\xc3\xad, co se od \
n\xc4\x9bj li\xc5\xa1\xc3\xad; ka\xc5\
\xbed\xc3\xbd kl\xc3\xad\xc4\x8d sm\xc3\xad\
 chyb\xc4\x9bt.\x0a<code>\
[test]</code> a \
<code>[limits]</\
code> plat\xc3\xad pro\
 smy\xc4\x8dku polohy,\
\x0a<code>[process.\
test]</code> a <\
code>[process.li\
mits]</code> pro\
 procesn\xc3\xad smy\xc4\x8d\
ku E04, jej\xc3\xad\xc5\xbe\x0a\
vlastn\xc3\xad v\xc3\xbdchoz\
\xc3\xad hodnoty jsou \
okna skok\xc5\xaf 1,5 \
s, rozm\xc3\xadt\xc3\xa1n\xc3\xad \
od 0,2 do 20 Hz,\
 doba n\xc3\xa1b\xc4\x9bhu\x0a\xe2\
\x89\xa4 0,4 s, doba u\
st\xc3\xa1len\xc3\xad \xe2\x89\xa4 0,\
8 s a \xe2\x88\x923 dB \xe2\x89\
\xa5 0,8 Hz. Mez je\
 <code>{ min = \xe2\
\x80\xa6 }</code>,\x0a<co\
de>{ max = \xe2\x80\xa6 }\
</code> nebo obo\
j\xc3\xad; \xc4\x8d\xc3\xadsla v s\
ouboru s desetin\
nou te\xc4\x8dkou.</p>\
\x0a<pre>\x0aname = \x22P\
RM9-06 v\xc3\xbdstupn\xc3\
\xad zkou\xc5\xa1ka\x22\x0a[tes\
t]\x0astep_amplitud\
es_pct = [5, 25,\
 90]\x0astep_durati\
on_s = 0.15\x0astat\
ic_period_s = 20\
\x0a[limits]\x0astep_o\
vershoot_pct = {\
 max = 15 }\x0astep\
_rise_s = { max \
= 0.03 }\x0abode_ba\
ndwidth_hz = { m\
in = 15 }\x0astatic\
_hysteresis_pct \
= { max = 2 }\x0a\x0a[\
process.test]   \
   # E04 v re\xc5\xbei\
mu regulace 4\x0ast\
ep_duration_s = \
2.0\x0a[process.lim\
its]\x0astep_rise_s\
 = { max = 0.5 }\
\x0astep_settling_s\
 = { max = 1.0 }\
\x0aflow_gain = { m\
in = 3 }\x0a</pre>\x0a\
<p>Hodnoty: step\
_overshoot_pct, \
step_rise_s, ste\
p_settling_s, bo\
de_bandwidth_hz,\
\x0abode_phase90_hz\
, static_gain, s\
tatic_hysteresis\
_pct, static_lin\
earity_pct,\x0astat\
ic_dead_band_pct\
, flow_gain, flo\
w_dead_band_pct.\
 Nezn\xc3\xa1m\xc3\xbd kl\xc3\xad\xc4\
\x8d nebo chybn\xc3\xa1 h\
odnota se\x0aodm\xc3\xadt\
ne s uveden\xc3\xadm s\
ouboru a kl\xc3\xad\xc4\x8de\
.</p>\x0a<p>Karta <\
b>P\xc5\x99echodov\xc3\xa1 c\
harakteristika</\
b> osciloskopu m\
\xc4\x9b\xc5\x99\xc3\xad p\xc5\x99ekmit,\
 dobu n\xc3\xa1b\xc4\x9bhu a\
 dobu\x0aust\xc3\xa1len\xc3\xad\
 ka\xc5\xbed\xc3\xa9ho zobra\
zen\xc3\xa9ho skoku.</\
p>\x0a</body>\x0a</htm\
l>\x0a\
\x00\x00%u\
<\
!DOCTYPE html>\x0a<\
html lang=\x22de\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>prm9tool \xe2\x80\x93 \
Hilfe</title></h\
ead>\x0a<body>\x0a<h1>\
prm9tool</h1>\x0a<p\
>prm9tool stellt\
 die Parameter v\
on PRM9-Proporti\
onal-Wegeventile\
n mit integriert\
er\x0adigitaler Ele\
ktronik ein \xe2\x80\x93 \
\xc3\xbcber USB oder a\
m eingebauten em\
ulierten Ventil.\
 Die Parameter\x0ab\
eschreibt die Be\
triebsanleitung \
des Ventils (Kap\
itel 8); diese S\
eite beschreibt \
das\x0aProgramm.</p\
>\x0a\x0a<p><b>Weitere\
 Seiten:</b> <a \
href=\x22can_de.htm\
l\x22>CAN-Bus und C\
ANopen</a> \xc2\xb7 <a\
 href=\x22tuning_de\
.html\x22>Einstellu\
ng und Charakter\
isierung</a> \xc2\xb7 \
<a href=\x22compare\
_de.html\x22>Parame\
ters\xc3\xa4tze vergle\
ichen</a> \xc2\xb7 <a \
href=\x22history_de\
.html\x22>Verlauf e\
ines Ventils</a>\
. In einem Fenst\
er \xc3\xb6ffnet <b>F1\
</b> die Seite d\
azu.</p>\x0a\x0a<h2>St\
art</h2>\x0a<ul>\x0a<l\
i><code>prm9tool\
</code> \xc3\xb6ffnet \
das Fenster mit \
einem neuen Para\
metersatz.</li>\x0a\
<li><code>prm9to\
ol DATEI.prm</co\
de> \xc3\xb6ffnet eine\
 Parameterdatei.\
</li>\x0a<li><code>\
prm9tool --emula\
tor [TYPSCHL\xc3\x9cSS\
EL[:SERIENNUMMER\
]]</code> starte\
t online mit ein\
em\x0aemulierten Ve\
ntil (Standard-T\
ypschl\xc3\xbcssel <co\
de>PRM9-06.3Z11/\
30-24E02S02-CA</\
code>).</li>\x0a</u\
l>\x0a\x0a<h2>Das Fens\
ter</h2>\x0a<p>Haup\
tmen\xc3\xbc, Werkzeug\
leiste, Hauptfl\xc3\
\xa4che und Statusz\
eile. Die Status\
zeile zeigt den\x0a\
Kommunikationsmo\
dus, den Zustand\
 des Ventils (<i\
>ok</i> oder den\
 aktiven Fehler)\
, die\x0aFirmware-V\
ersion, den Typs\
chl\xc3\xbcssel und de\
n Dateinamen (<b\
>*</b>: ungespei\
cherte \xc3\x84nderung\
en)\x0aund zuletzt \
die Berechtigung\
sstufe. Der Modu\
s lautet VERBIND\
EN, solange ein \
eben verbundenes\
\x0aVentil mit dem \
Parametersatz ve\
rglichen wird, u\
nd ONLINE, sobal\
d beide \xc3\xbcberein\
stimmen.</p>\x0a<p>\
Die Hauptfl\xc3\xa4che\
 zeigt eine von \
drei Ansichten: \
das <b>Ablaufdia\
gramm</b> (ein K\
lick auf\x0aeinen B\
lock stellt sein\
e Parameter ein,\
 ein Klick auf e\
inen roten Messp\
unkt zeigt ihn i\
m\x0aOszilloskop), \
die <b>Parameter\
liste</b> (Doppe\
lklick auf eine \
Zeile \xc3\xa4ndert de\
n Wert; Werte,\x0ad\
ie von der Werks\
einstellung abwe\
ichen, sind herv\
orgehoben; Suche\
 und \xe2\x80\x9eNur ge\xc3\xa4\
nderte\xe2\x80\x9c\x0afilter\
n die Liste) und\
 das <b>Oszillos\
kop</b> (nur onl\
ine, h\xc3\xb6chstens \
drei Messpunkte)\
.</p>\x0a\x0a<h2>Berec\
htigungsstufen</\
h2>\x0a<p><b>Basis<\
/b> zeigt die gr\
undlegenden Eins\
tellungen; in de\
r Basisstufe wer\
den die vier\x0aRam\
pen gemeinsam ei\
ngestellt. <b>Ex\
perte</b> erg\xc3\xa4n\
zt die Regler, d\
ie Linearisierun\
gen und\x0adie Eins\
tellungen des ex\
ternen Sensors u\
nd ist durch ein\
 Passwort gesch\xc3\
\xbctzt. Das Passwo\
rt\x0aim Auslieferu\
ngszustand laute\
t <code>expert</\
code>; in der Ex\
pertenstufe \xc3\xa4nd\
ern Sie es unter\
\x0aAnsicht \xe2\x86\x92 Ber\
echtigungsstufe \
\xe2\x86\x92 Expertenpass\
wort \xc3\xa4ndern. Da\
s Programm speic\
hert nur einen\x0ag\
esalzenen Hash d\
avon.</p>\x0a<p>Die\
 Berechtigungsst\
ufen sch\xc3\xbctzen v\
or versehentlich\
en \xc3\x84nderungen, \
nicht vor jemand\
em, der die\x0aEins\
tellungen des Pr\
ogramms bearbeit\
en kann: Wird de\
r Eintrag\x0a<code>\
access/expert_pa\
ssword</code> au\
s den Einstellun\
gen entfernt, gi\
lt wieder das Pa\
sswort\x0ades Ausli\
eferungszustands\
. Eine Parameter\
datei enth\xc3\xa4lt a\
lle Werte, unabh\
\xc3\xa4ngig von der S\
tufe:\x0aSendet ein\
 Benutzer der St\
ufe Basis ein Do\
kument, dessen E\
xpertenwerte von\
 denen des Venti\
ls\x0aabweichen, fr\
agt das Programm\
 zuerst nach.</p\
>\x0a\x0a<h2>Online un\
d offline</h2>\x0a<\
p>Kommunikation \
\xe2\x86\x92 HID-Konfigur\
ation listet die\
 \xc3\xbcber USB anges\
chlossenen und d\
ie emulierten\x0aVe\
ntile; ein emuli\
ertes Ventil f\xc3\xbc\
gen Sie mit Typs\
chl\xc3\xbcssel und Se\
riennummer hinzu\
.\x0aKommunikation \
\xe2\x86\x92 Online-Modus\
 verbindet. Ein \
aus einem andere\
n Ventil (andere\
 Seriennummer) g\
elesenes Dokumen\
t wird zuerst ge\
nannt: damit wei\
terarbeiten oder\
 offline gehen. \
Weicht der ge\xc3\xb6f\
fnete Parameters\
atz vom Ventil a\
b,\x0azeigt das Pro\
gramm die Unters\
chiede und fragt\
, ob die Werte d\
es Ventils \xc3\xbcber\
nommen, die\x0aWert\
e des Dokuments \
gesendet (Hochla\
den) oder abgebr\
ochen werden sol\
l. Online geht j\
ede\x0a\xc3\x84nderung so\
fort an das Vent\
il und in das Do\
kument, offline \
nur in das Dokum\
ent. \xc3\x9cbernimmt \
das Dokument die\
 Werte eines Ven\
tils eines ander\
en Typs, wird es\
 ein neues, unge\
speichertes Doku\
ment (seine Date\
i beh\xc3\xa4lt, was s\
ie enthielt); ei\
n in ein Ventil \
hochgeladenes od\
er mit ihm \xc3\xbcber\
einstimmendes Do\
kument geh\xc3\xb6rt v\
on da an zu dies\
em Ventil (SNV, \
und keine Frage \
beim erneuten Ve\
rbinden).</p>\x0a<p\
><b>Wenn das Ven\
til wegf\xc3\xa4llt</b\
> (USB-Kabel gez\
ogen, Spannung a\
us und ein, CAN-\
Bus-off, ein\x0aNeu\
start, nach dem \
es nicht zur\xc3\xbcck\
kommt), geht das\
 Programm offlin\
e, beh\xc3\xa4lt alle \
Werte und\x0asucht \
das Ventil von s\
elbst: die Statu\
sleiste zeigt <i\
>Modus: NEU VERB\
INDEN\xe2\x80\xa6 3 s</i>\
. Es sucht\x0aauf d\
erselben Verbind\
ung \xe2\x80\x94 \xc3\xbcber CA\
N auch unter ein\
er anderen Knote\
nnummer, wenn di\
e\x0aSeriennummer (\
0x1018/4) sagt, \
dass es dasselbe\
 Ventil ist. Ist\
 das Ventil zur\xc3\
\xbcck, liest das\x0aP\
rogramm es und v\
ergleicht es wie\
 beim Online-Geh\
en mit dem Dokum\
ent (<i>Wieder o\
nline</i>,\x0awenn \
sie \xc3\xbcbereinstim\
men); ohne Sie w\
ird nichts ins V\
entil geschriebe\
n: online ge\xc3\xa4nd\
erte Werte,\x0adie \
das Ventil beim \
Aus- und Einscha\
lten verloren ha\
t, werden im Unt\
erschiede-Dialog\
\x0aangeboten, nich\
t gesendet. Ein \
durch die Verbin\
dung abgebrochen\
er Tuning-Test s\
chreibt\x0azur\xc3\xbcck,\
 was er ge\xc3\xa4nder\
t hatte, sobald \
das Ventil wiede\
r da ist, und me\
ldet es. Das Osz\
illoskop zeichne\
t weiter auf; de\
r Sollwertgenera\
tor und ein\x0aTuni\
ng-Test bleiben \
angehalten, bis \
Sie sie starten \
(\xc3\xbcber CAN wird \
die Empfangs\xc3\xbcbe\
rwachung,\x0adie ei\
n abgebrochener \
Sollwertgenerato\
r im Ventil gese\
tzt hatte, zur\xc3\xbc\
ckgesetzt, sobal\
d das\x0aVentil wie\
der da ist, und \
die Statusleiste\
 meldet es). Ein\
 Bus-Off Ihres C\
AN-Adapters wird\
 in\x0ader Statusle\
iste genannt; da\
s Ventil wird wi\
edergefunden, so\
bald der Adapter\
 wieder am Bus\x0ai\
st. Ein abgebroc\
henes Hochladen \
meldet, was\x0agesc\
hah und was das \
Ventil enth\xc3\xa4lt;\
 es wird nicht f\
ortgesetzt. Ein \
anderes Ventil (\
andere\x0aSeriennum\
mer) an der Stel\
le des verlorene\
n ist ein neues \
Ventil: das Prog\
ramm sagt es und\
\x0averbindet sich \
nicht von selbst\
. Selbst online \
oder offline geh\
en beendet die S\
uche. Mit\x0aeinem \
emulierten Venti\
l zeigen es Vent\
il \xe2\x86\x92 Emulierte\
s Ventil \xe2\x86\x92 <b>\
USB-Kabel ziehen\
</b> und\x0a<b>USB-\
Kabel wieder ein\
stecken</b>.</p>\
\x0a<p>Online ge\xc3\xa4n\
derte Werte sind\
 im Ventil aktiv\
, aber noch nich\
t gespeichert: b\
eim Wechsel\x0aauf \
offline bietet d\
as Programm an, \
sie zu speichern\
, und Ventil \xe2\x86\x92\
 <b>Im Ventil sp\
eichern</b>\x0aspei\
chert sie sofort\
 (womit das Vent\
il arbeitet, dam\
it startet es au\
ch; im Verlauf\x0af\
estgehalten). <b\
>In das Ventil h\
ochladen</b>\x0asch\
reibt alle Werte\
, liest sie zur\xc3\
\xbcck, vergleicht \
und speichert si\
e; gespeichert w\
ird nur,\x0awenn je\
der Wert best\xc3\xa4t\
igt wurde. Vor d\
em ersten Hochla\
den in ein Venti\
l sichert das\x0aPr\
ogramm dessen ei\
gene Parameter i\
m Benutzerdateno\
rdner (<code>bac\
kups/&lt;Serienn\
ummer&gt;/</code\
>).</p>\x0a<p><b>Ve\
ntil neu starten\
</b> und <b>Werk\
seinstellungen w\
iederherstellen<\
/b> sind nur bei\
\x0agetrennter Hydr\
aulik erlaubt; d\
as Programm l\xc3\xa4s\
st Sie das best\xc3\
\xa4tigen.</p>\x0a<p>V\
entil \xe2\x86\x92 <b>Dur\
ch Neustart pr\xc3\xbc\
fen\xe2\x80\xa6</b> (nach\
 dem Hochladen, \
solange dasselbe\
 Ventil online\x0ab\
leibt) startet d\
as Ventil \xe2\x80\x93 na\
ch derselben Bes\
t\xc3\xa4tigung zur Hy\
draulik \xe2\x80\x93 neu \
und liest seine\x0a\
Parameter zur\xc3\xbcc\
k: die Statuszei\
le meldet \xe2\x80\x9e\xe2\x80\xa6\
 unver\xc3\xa4ndert zu\
r\xc3\xbcckgelesen: na\
ch einem Neustar\
t\x0agepr\xc3\xbcft\xe2\x80\x9c, o\
der eine Meldung\
 nennt jeden Wer\
t, den das Venti\
l nicht behalten\
 hat (erwartet \xe2\
\x86\x92\x0azur\xc3\xbcckgelese\
n), und der Verl\
auf h\xc3\xa4lt das Er\
gebnis fest. Die\
 Meldung des Hoc\
hladens sagt, wi\
e\x0adas Ventil die\
 Werte beh\xc3\xa4lt: \
\xe2\x80\x9emit 0x1010 ge\
speichert\xe2\x80\x9c ode\
r, \xc3\xbcber CANopen\
 bei einem Venti\
l\x0aohne Speicherb\
efehl, \xe2\x80\x9evom Ve\
ntil wie geschri\
eben behalten (e\
s hat keinen Spe\
icherbefehl)\xe2\x80\x9c.\
\x0aOnline ge\xc3\xa4nder\
te, noch nicht g\
espeicherte Wert\
e m\xc3\xbcssen zuerst\
 gespeichert wer\
den (ein Neustar\
t\x0aw\xc3\xbcrde sie ver\
lieren). Meldet \
sich das Ventil \
nicht wieder, ge\
ht das Programm \
offline und sagt\
,\x0awas das Ventil\
 nach bestem Wis\
sen enth\xc3\xa4lt; da\
s Dokument beh\xc3\xa4\
lt jeden Wert.</\
p>\x0a\x0a<h2>Dateien<\
/h2>\x0a<p>Paramete\
rdateien (<code>\
*.prm</code>) si\
nd Textdateien. \
\xc3\x96ffnen, Speiche\
rn, Speichern\x0aun\
ter, die zuletzt\
 ge\xc3\xb6ffneten Dat\
eien und Drag &a\
mp; Drop funktio\
nieren wie gewoh\
nt; vor dem\x0aVerl\
ust ungespeicher\
ter \xc3\x84nderungen \
fragt das Progra\
mm nach. Jede \xc3\x84\
nderung l\xc3\xa4sst s\
ich\x0ar\xc3\xbcckg\xc3\xa4ngig\
 machen (Strg+Z)\
 und wiederherst\
ellen (Strg+Y). \
Datei \xe2\x86\x92 Drucke\
n und Datei \xe2\x86\x92 \
PDF\x0aexportieren \
erzeugen ein Par\
ameterprotokoll \
mit Typschl\xc3\xbcsse\
l, Seriennummer,\
 Firmware, Datei\
,\x0aDatum, Berecht\
igungsstufe, dem\
 Ablaufdiagramm \
und allen Parame\
tern mit Einheit\
. Seit dem\x0aSpeic\
hern ge\xc3\xa4nderte \
Werte sind mit <\
b>*</b> markiert\
, und die Zeile \
\xe2\x80\x9eDatei\xe2\x80\x9c sagt\
 es; jede Seite\x0a\
nennt Typschl\xc3\xbcs\
sel und Seriennu\
mmer und tr\xc3\xa4gt \
ihre Seitenzahl;\
 die letzte Seit\
e hat eine Zeile\
\x0af\xc3\xbcr Datum, Nam\
e und Unterschri\
ft.</p>\x0a<p><b>Ei\
n Ventil sichern\
</b>: online geh\
en, Ventil \xe2\x86\x92 A\
us dem Ventil he\
runterladen, dan\
n\x0aDatei \xe2\x86\x92 <b>S\
icherungskopie s\
peichern\xe2\x80\xa6</b> \
(vorgeschlagener\
 Name: Typschl\xc3\xbc\
ssel, Seriennumm\
er,\x0aDatum und Uh\
rzeit). Die Kopi\
e wird geschrieb\
en, das ge\xc3\xb6ffne\
te Dokument blei\
bt, was es war:\x0a\
sp\xc3\xa4tere \xc3\x84nderu\
ngen werden in s\
eine eigene Date\
i gespeichert, n\
ie in die Sicher\
ung. Speichern\x0au\
nter dagegen mac\
ht die neue Date\
i zum ge\xc3\xb6ffnete\
n Dokument.</p>\x0a\
\x0a<h2>Tastatur</h\
2>\x0a<table>\x0a<tr><\
td>Strg+O / Strg\
+S / Strg+Umscha\
lt+S</td><td>\xc3\x96f\
fnen / Speichern\
 / Speichern unt\
er</td></tr>\x0a<tr\
><td>Strg+Z / St\
rg+Y</td><td>R\xc3\xbc\
ckg\xc3\xa4ngig / Wied\
erherstellen</td\
></tr>\x0a<tr><td>S\
trg+P / Strg+E</\
td><td>Drucken /\
 PDF exportieren\
</td></tr>\x0a<tr><\
td>Strg+1 / Strg\
+2 / Strg+3 / St\
rg+4</td><td>Abl\
aufdiagramm / Pa\
rameterliste / O\
szilloskop / CAN\
open-Fenster</td\
></tr>\x0a<tr><td>F\
5 / Umschalt+F5<\
/td><td>Online /\
 Offline</td></t\
r>\x0a<tr><td>Strg+\
U / Strg+D</td><\
td>In das Ventil\
 hochladen / Aus\
 dem Ventil heru\
nterladen</td></\
tr>\x0a<tr><td>Strg\
+T / Strg+I / St\
rg+H</td><td>Ven\
tilauswahl / Ven\
tilstatus / HID-\
Konfiguration</t\
d></tr>\x0a</table>\
\x0a<p><b>Skripte u\
nd Pr\xc3\xbcfst\xc3\xa4nde<\
/b>: das Ventil \
aus Python und S\
hell-Skripten, <\
a href=\x22scriptin\
g_en.html\x22>auf d\
ieser Seite</a> \
(auf Englisch).<\
/p>\x0a</body>\x0a</ht\
ml>\x0a\
\x00\x00\x07\xa7\
<\
!DOCTYPE html>\x0a<\
html lang=\x22en\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>History of a \
valve</title></h\
ead>\x0a<body>\x0a<p><\
a href=\x22help_en.\
html\x22>prm9tool h\
elp</a></p>\x0a<h1>\
History of a val\
ve</h1>\x0a<p>Every\
 operation on a \
valve's paramete\
rs is recorded w\
ith time (UTC), \
serial number, t\
ype\x0akey, firmwar\
e, link, program\
 version, user a\
nd station: read\
ing, uploading (\
and what for),\x0ab\
ackups, storing,\
 factory values,\
 test reports, a\
nd what you did \
online \xe2\x80\x94 value\
s taken from\x0aa c\
ompared file or \
from the history\
, tuning accepte\
d \xe2\x80\x94 with each \
value changed. E\
ach valve's\x0areco\
rds form a hash \
chain, so a chan\
ged record is fo\
und.</p>\x0a<p>Valv\
e \xe2\x86\x92 <b>History\
\xe2\x80\xa6</b> lists th\
e records of the\
 connected valve\
 (or of a serial\
 number\x0ayou type\
). The column <b\
>What was done</\
b> says each rec\
ord's meaning, e\
.g. \xe2\x80\x9cTuning ac\
cepted,\x0awritten \
online: Autotune\
; POSKP 0.4 \xe2\x86\x92 \
0.55\xe2\x80\x9d.</p>\x0a<ul\
>\x0a<li><b>Compare\
 the two selecte\
d records</b>: t\
he difference in\
 the compare vie\
w; tick values\x0aa\
nd take them int\
o the document o\
r write them int\
o the valve.</li\
>\x0a<li><b>Restore\
 into the docume\
nt</b>: a record\
's whole set, ty\
pe key included \
(one undo\x0astep).\
 <b>Restore to t\
he valve</b>: a \
transactional up\
load into the va\
lve the record c\
ame\x0afrom (online\
 with it).</li>\x0a\
<li><b>Export\xe2\x80\xa6\
</b>: a record a\
s <code>*.prm</c\
ode> or CSV. <b>\
Database\xe2\x80\xa6</b>:\
 SQLite on this\x0a\
computer, or a P\
ostgreSQL server\
 for a line of s\
tations, and wha\
t to do when it \
cannot be\x0areache\
d.</li>\x0a</ul>\x0a<p\
>Autotune runs, \
frequency respon\
ses, test report\
s (with the figu\
res that failed \
and,\x0aonce saved,\
 the PDF) and re\
starts on the va\
lve are recorded\
 too. <b>Double-\
click</b> a reco\
rd\x0afor its detai\
ls \xe2\x80\x94 every fie\
ld, <b>Open the \
PDF</b>, <b>Comp\
are with the rec\
ord before</b> \xe2\
\x80\x94 or,\x0awith two \
records selected\
, for their comp\
arison. A valve'\
s type key never\
 changes: record\
s of\x0aanother typ\
e under the same\
 serial number (\
emulated valves \
of two runs may \
share one) are\x0am\
arked \xe2\x9a\xa0 and th\
e window says so\
.</p>\x0a</body>\x0a</\
html>\x0a\
\x00\x00\x0f\x93\
<\
!DOCTYPE html>\x0a<\
html lang=\x22cs\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>Sb\xc4\x9brnice CAN\
 a CANopen</titl\
e></head>\x0a<body>\
\x0a<p><a href=\x22hel\
p_cs.html\x22>N\xc3\xa1po\
v\xc4\x9bda prm9tool</\
a></p>\x0a<h1>Sb\xc4\x9br\
nice CAN a CANop\
en</h1>\x0a<p>Venti\
l -CA komunikuje\
 tak\xc3\xa9 p\xc5\x99es CAN\
open (n\xc3\xa1vod, ka\
pitola 7). prm9t\
ool je pak CANop\
en\x0amaster, p\xc5\x99es\
 kter\xc3\xbdkoli adap\
t\xc3\xa9r CAN, kter\xc3\xbd\
 podporuje pytho\
n-can (PEAK, Kva\
ser, IXXAT, Vect\
or,\x0aCANable/slca\
n, SocketCAN).</\
p>\x0a<h2>P\xc5\x99ipojen\
\xc3\xad p\xc5\x99es CAN</h2\
>\x0a<ol>\x0a<li>Komun\
ikace \xe2\x86\x92 <b>Sb\xc4\
\x9brnice CAN\xe2\x80\xa6</b\
>: zvolte rozhra\
n\xc3\xad, kan\xc3\xa1l a p\xc5\
\x99enosovou rychlo\
st a pak\x0a<b>Proh\
ledat sb\xc4\x9brnici<\
/b>. Ka\xc5\xbed\xc3\xbd uze\
l, kter\xc3\xbd odpov\xc3\
\xad, se vyp\xc3\xad\xc5\xa1e s\
e stavem NMT, he\
artbeatem\x0aa posl\
edn\xc3\xad zpr\xc3\xa1vou E\
MCY; uzly, kter\xc3\
\xa9 nejsou ventily\
 PRM9, zvolit ne\
lze.</li>\x0a<li>Zv\
olte ventil a st\
iskn\xc4\x9bte OK: pro\
gram se s n\xc3\xadm s\
poj\xc3\xad (<code>can\
:UZEL</code>). S\
kute\xc4\x8dn\xc3\xbd\x0aventil\
 neuv\xc3\xa1d\xc3\xad sv\xc5\xafj\
 \xc3\xbapln\xc3\xbd typov\xc3\xbd\
 kl\xc3\xad\xc4\x8d: zadejte\
 ten ze \xc5\xa1t\xc3\xadtku\
 ventilu; progra\
m si ho pamatuje\
\x0apodle v\xc3\xbdrobn\xc3\xad\
ho \xc4\x8d\xc3\xadsla.</li>\
\x0a</ol>\x0a<h2>Uvede\
n\xc3\xad do provozu</\
h2>\x0a<p>Ventil -C\
A ve stavu p\xc5\x99i \
dod\xc3\xa1n\xc3\xad \xc4\x8dek\xc3\xa1 \
na sv\xc5\xafj master:\
 NMT pre-operati\
onal, stav za\xc5\x99\xc3\
\xadzen\xc3\xad\x0aINIT; nes\
leduje \xc5\xbe\xc3\xa1danou\
 hodnotu. Ventil\
 \xe2\x86\x92 <b>Stav ven\
tilu</b>, skupin\
a Uveden\xc3\xad do pr\
ovozu:\x0astiskn\xc4\x9bt\
e <b>NMT start</\
b> a pak <b>Uvol\
nit</b> (\xc5\x99\xc3\xaddic\
\xc3\xad slovo 08h \xe2\x86\x92\
 09h \xe2\x86\x92 0Bh \xe2\x86\x92\
 0Fh). \xc5\x98\xc3\xa1dek\x0ap\
od tla\xc4\x8d\xc3\xadtky \xc5\x99\
\xc3\xadk\xc3\xa1, co je\xc5\xa1t\xc4\
\x9b chyb\xc3\xad. \xe2\x80\x9eZab\
lokovat\xe2\x80\x9c a \xe2\x80\x9e\
NMT stop\xe2\x80\x9c to v\
r\xc3\xa1t\xc3\xad zp\xc4\x9bt.</p\
>\x0a<h2>Objekty a \
konfigurace</h2>\
\x0a<ul>\x0a<li>N\xc3\xa1hle\
d \xe2\x86\x92 <b>Slovn\xc3\xad\
k objekt\xc5\xaf\xe2\x80\xa6</b\
> p\xc5\x99e\xc4\x8dte ka\xc5\xbed\
\xc3\xbd objekt; do vy\
hled\xc3\xa1vac\xc3\xadho \xc5\x99\
\xc3\xa1dku napi\xc5\xa1te\x0ai\
ndex, n\xc3\xa1zev neb\
o hodnotu. V exp\
ertn\xc3\xad \xc3\xbarovni z\
ap\xc3\xad\xc5\xa1e dvojklik\
 zapisovateln\xc3\xbd \
objekt.</li>\x0a<li\
>N\xc3\xa1hled \xe2\x86\x92 <b>\
Okno CANopen</b>\
: Node ID, p\xc5\x99en\
osov\xc3\xa1 rychlost \
a zakon\xc4\x8dovac\xc3\xad \
odpor. Ventil \xc4\x8d\
te\x0asv\xc3\xa9 oto\xc4\x8dn\xc3\xa9\
 p\xc5\x99ep\xc3\xadna\xc4\x8de po\
 zapnut\xc3\xad; zm\xc4\x9bn\
\xc4\x9bn\xc3\xa9 Node ID ne\
bo rychlost plat\
\xc3\xad po restartu a\
 po Ventil \xe2\x86\x92\x0aR\
estart ventilu n\
ajde prm9tool ve\
ntil na nov\xc3\xa9 ad\
rese.</li>\x0a<li>S\
oubor \xe2\x86\x92 <b>Exp\
ort DCF\xe2\x80\xa6</b> u\
lo\xc5\xbe\xc3\xad konfigura\
ci ventilu pro k\
onfigur\xc3\xa1tor PLC\
.</li>\x0a<li>Venti\
l \xe2\x86\x92 <b>Ulo\xc5\xbeit\
 do pam\xc4\x9bti vent\
ilu</b> trvale u\
lo\xc5\xbe\xc3\xad hodnoty, \
se kter\xc3\xbdmi vent\
il pracuje\x0a(obje\
kt 0x1010, nebo \
vlastn\xc3\xadm zp\xc5\xafso\
bem ventilu, kde\
 objekt chyb\xc3\xad).\
</li>\x0a<li>Ventil\
 bez objektu 0x1\
010 (seznam obje\
kt\xc5\xaf v n\xc3\xa1vodu h\
o nem\xc3\xa1) si ka\xc5\xbe\
dou hodnotu pone\
ch\xc3\xa1, jakmile\x0aje\
 zaps\xc3\xa1na: na\xc4\x8dt\
en\xc3\xad do ventilu \
zapisuje v po\xc5\x99a\
d\xc3\xad, kter\xc3\xa9 nikd\
y nezanech\xc3\xa1 kom\
binaci odm\xc3\xadtnut\
ou\x0apravidly, v\xc5\xa1\
e zp\xc4\x9btn\xc4\x9b na\xc4\x8dt\
e a ohl\xc3\xa1s\xc3\xad \xe2\x80\x9e\
ventil si hodnot\
y ponechal tak, \
jak byly zaps\xc3\xa1n\
y (nem\xc3\xa1\x0ap\xc5\x99\xc3\xadka\
z k ulo\xc5\xbeen\xc3\xad)\xe2\x80\
\x9c. Ventil \xe2\x86\x92 <b\
>Ov\xc4\x9b\xc5\x99it restar\
tem\xe2\x80\xa6</b> ho pa\
k restartuje (NM\
T reset node,\x0ahy\
draulika odpojen\
a) a zp\xc4\x9btn\xc4\x9b na\
\xc4\x8dte, zda si hod\
noty ponechal: \xe2\
\x80\x9eov\xc4\x9b\xc5\x99eno po r\
estartu\xe2\x80\x9c.</li>\
\x0a</ul>\x0a<p>Oscilo\
skop bere skute\xc4\
\x8dnou polohu z TP\
DO1; gener\xc3\xa1tor \
\xc5\xbe\xc3\xa1dan\xc3\xa9 hodnot\
y a zkou\xc5\xa1ky lad\
\xc4\x9bn\xc3\xad pos\xc3\xadlaj\xc3\xad\
\x0a\xc5\xbe\xc3\xa1danou hodno\
tu v RPDO1, jako\
 PLC.</p>\x0a<h2>Z\xc3\
\xa1znam a \xc4\x8dten\xc3\xad \
sb\xc4\x9brnice</h2>\x0a<\
p>Komunikace \xe2\x86\x92\
 <b>Sb\xc4\x9brnice CA\
N\xe2\x80\xa6</b> \xe2\x86\x92 <b>\
Zaznamenat\xe2\x80\xa6</b\
> zapisuje ka\xc5\xbed\
\xc3\xbd r\xc3\xa1mec sb\xc4\x9brn\
ice s jeho\x0a\xc4\x8dase\
m do souboru z\xc3\xa1\
znamu (ASC, BLF,\
 TRC nebo candum\
p log); z\xc3\xa1znam \
b\xc4\x9b\xc5\xbe\xc3\xad vedle v\xc5\
\xa1eho, co program\
\x0ana sb\xc4\x9brnici d\xc4\
\x9bl\xc3\xa1 (na\xc4\x8dten\xc3\xad \
do ventilu, test\
), a\xc5\xbe do <b>Uko\
n\xc4\x8dit z\xc3\xa1znam</b\
>. Komunikace \xe2\x86\
\x92 <b>CAN\x0az\xc3\xa1znam\
\xe2\x80\xa6</b> otev\xc5\x99e \
takov\xc3\xbd soubor, \
i po\xc5\x99\xc3\xadzen\xc3\xbd pr\
ogramem PCAN-Vie\
w, CANalyzer neb\
o\x0a<code>candump<\
/code>, a p\xc5\x99e\xc4\x8d\
te jej slovy: p\xc5\
\x99\xc3\xadkazy a stavy \
NMT ka\xc5\xbed\xc3\xa9ho uz\
lu, p\xc5\x99enosy SDO\
 se\x0ajm\xc3\xa9nem obje\
ktu, hodnotou v \
zobrazovan\xc3\xbdch j\
ednotk\xc3\xa1ch a p\xc5\x99\
eru\xc5\xa1en\xc3\xadm slovy\
, PDO podle pr\xc3\xa1\
v\xc4\x9b\x0aplatn\xc3\xa9ho ma\
pov\xc3\xa1n\xc3\xad, \xc5\x99\xc3\xaddi\
c\xc3\xad a stavov\xc3\xa9 s\
lovo jako zm\xc4\x9bny\
 stavu, EMCY pod\
le tabulky chyb \
n\xc3\xa1vodu,\x0aperioda\
 a rozptyl SYNC,\
 LSS. Filtruje s\
e podle uzlu a d\
ruhu; seznam ud\xc3\
\xa1lost\xc3\xad (uzel, k\
ter\xc3\xbd\x0azmlkl, EMC\
Y, opu\xc5\xa1t\xc4\x9bn\xc3\xbd D\
EVICE_MODE_ACTIV\
E, p\xc5\x99eru\xc5\xa1en\xc3\xad \
SDO) vybere jeji\
ch r\xc3\xa1mec. Na p\xc5\
\x99\xc3\xadkazov\xc3\xa9\x0a\xc5\x99\xc3\xa1d\
ce: <code>prm9to\
ol --record trac\
e.asc</code>, <c\
ode>prm9tool --d\
ecode trace.asc<\
/code>\x0a(<code>--\
json</code>, <co\
de>--csv</code>,\
 <code>--fail-on\
-incident</code>\
) a <code>prm9to\
ol\x0a--replay trac\
e.asc</code>.</p\
>\x0a</body>\x0a</html\
>\x0a\
\x00\x00\x18\xb0\
<\
!DOCTYPE html>\x0a<\
html lang=\x22en\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>Tuning and ch\
aracterization</\
title></head>\x0a<b\
ody>\x0a<p><a href=\
\x22help_en.html\x22>p\
rm9tool help</a>\
</p>\x0a<h1>Tuning \
and characteriza\
tion</h1>\x0a<p>Ope\
n the Tuning win\
dow from the osc\
illoscope (<b>Tu\
ning and charact\
erization\xe2\x80\xa6</b>\
) or from\x0athe co\
ntroller blocks \
of the flow diag\
ram. Online it m\
oves the connect\
ed valve; offlin\
e it\x0aruns on an \
emulated copy of\
 the document's \
valve. The valve\
 must follow its\
 setpoint (a -CA\
\x0avalve: NMT star\
t and Enable fir\
st); a test offe\
rs to enable it.\
</p>\x0a<p><b>Warni\
ng:</b> every te\
st moves the spo\
ol (on an E04 al\
so the actuator)\
. Make sure the\x0a\
machine may move\
. <b>Stop</b> en\
ds a test at onc\
e and puts the v\
alve back as it \
was.</p>\x0a\x0a<h2>Th\
e loop</h2>\x0a<p><\
b>Loop</b> choos\
es what the test\
s act on. <b>Pos\
ition controller\
 (spool)</b>: th\
e setpoint\x0ais th\
e spool position\
 (control mode 2\
, CTRLMODE). <b>\
Process controll\
er (E04)</b>: th\
e\x0asetpoint is th\
e process value \
of the external \
sensor, which th\
e process contro\
ller closes\x0aover\
 the spool and t\
he actuator (con\
trol mode 4, the\
 E04 default). A\
n E04 in control\
 mode 4\x0aopens on\
 the process loo\
p; the position \
loop needs contr\
ol mode 2, set w\
hile the valve i\
s not\x0aenabled.</\
p>\x0a\x0a<h2>E04: tun\
ing the process \
loop</h2>\x0a<ol>\x0a<\
li>Set up the ex\
ternal sensor fi\
rst (the paramet\
ers \x22External se\
nsor\x22: signal ty\
pe\x0aSENSTYPE, pol\
arity, gain and \
offset), so that\
 the process act\
ual value follow\
s the actuator\x0ao\
ver its range in\
 the right direc\
tion. Check it o\
n the oscillosco\
pe (process actu\
al value)\x0awhile \
the actuator mov\
es slowly.</li>\x0a\
<li>Leave the co\
ntrol mode at 4 \
and choose <b>Pr\
ocess controller\
 (E04)</b>.</li>\
\x0a<li>The actuato\
r integrates: it\
s position keeps\
 changing as lon\
g as the spool i\
s open.\x0aThe auto\
tune's defaults \
follow the loop:\
 a 20 % step and\
 a settling targ\
et of 500 ms\x0a(th\
e spool's 40 ms \
cannot be reache\
d by an actuator\
). Raise the tar\
get for a slow o\
r heavy\x0aactuator\
.</li>\x0a<li>Run t\
he autotune, che\
ck its proposal \
(the profile's s\
teps both ways a\
nd its static\x0ate\
st), accept it, \
then Valve \xe2\x86\x92 S\
tore in valve.</\
li>\x0a<li>With an \
overlapped spool\
, the <b>Flow ch\
aracteristic (E0\
4)</b> page meas\
ures the dead ba\
nd\x0aand proposes \
OFFSETPOS/OFFSET\
NEG for the proc\
ess loop.</li>\x0a<\
/ol>\x0a\x0a<h2>Access\
 level and fault\
s</h2>\x0a<p>Contro\
ller gains, line\
arizations and o\
ffsets can be ch\
anged at <b>Expe\
rt</b> access le\
vel\x0aonly (View \xe2\
\x86\x92 Access level)\
. A test whose r\
esult could not \
be accepted at t\
he present level\
\x0aasks before it \
starts; its resu\
lt stays on the \
page, so you can\
 switch to Exper\
t afterwards\x0aand\
 accept it witho\
ut running the t\
est again.</p>\x0a<\
p>A valve that h\
olds a fault (FA\
ULT_HOLD, FAULT)\
 does not follow\
 its setpoint: t\
he test is\x0arefus\
ed before it sta\
rts and the stat\
us line says why\
. To leave FAULT\
_HOLD remove the\
 cause\x0a(Valve \xe2\x86\
\x92 Valve status l\
ists the active \
error), then pre\
ss <b>Enable</b>\
 there: its firs\
t\x0acontrol word 0\
8h is the fault \
reset (manual ta\
bles 7-19 and 7-\
20, transition 1\
0), 09h \xe2\x86\x92 0Bh \
\xe2\x86\x92 0Fh enable\x0at\
he valve again. \
A valve without \
CANopen comes ou\
t of a fault wit\
h Valve \xe2\x86\x92 Rest\
art valve.</p>\x0a\x0a\
<h2>The pages</h\
2>\x0a<ul>\x0a<li><b>A\
utotune</b>: mod\
el-based (a few \
steps, a fitted \
model, gains tha\
t do not oscilla\
te) or\x0athe criti\
cal-gain rule. T\
he proposal is s\
hown against the\
 present gains; \
<b>Accept the\x0apr\
oposed gains</b>\
 puts them into \
the document (on\
e undo step; onl\
ine into the val\
ve too,\x0arecorded\
 in the history)\
. Store them wit\
h Valve \xe2\x86\x92 Stor\
e in valve.</li>\
\x0a<li><b>Frequenc\
y response</b>: \
a sine sweep aro\
und an operating\
 point; the \xe2\x88\x923\
 dB and \xe2\x88\x9290\xc2\xb0\x0a\
frequencies (the\
 sweep's range f\
ollows the loop:\
 1 \xe2\x80\xa6 200 Hz fo\
r the spool, 0.2\
 \xe2\x80\xa6 20 Hz for\x0at\
he process loop)\
.</li>\x0a<li><b>St\
atic characteris\
tic</b>: a slow \
triangle; hyster\
esis, linearity \
and dead band, a\
nd a\x0aproposed li\
nearization.</li\
>\x0a<li><b>Test re\
port</b>: an acc\
eptance profile \
(steps, sweep, s\
tatic test and t\
heir limits)\x0arun\
 in one go; the \
report names the\
 loop it tested,\
 and the PDF nam\
es type key and \
serial\x0anumber on\
 every page and \
lists the parame\
ter set in displ\
ay units; the ra\
w data go to CSV\
\x0abeside it. Step\
 figures are mea\
sured against th\
e setpoint: a st\
ep that did not \
reach it is\x0a\x22not\
 reached\x22 and fa\
ils.</li>\x0a<li><b\
>Birth certifica\
te</b> (online):\
 <b>Compare with\
 birth certifica\
te</b> plays a s\
hort\x0afield signa\
ture (a small an\
d a large step e\
ach way, a short\
 sweep around th\
e valve's\x0abandwi\
dth, a hysteresi\
s loop; at most \
20 s of motion) \
and compares eac\
h figure with th\
e\x0avalve's end-of\
-line test kept \
in the history f\
or its serial: t\
oday, then, the \
change and the\x0ad\
rift limit (the \
profile's <code>\
[drift]</code> p\
art, e.g.\x0a<code>\
bode_phase90_hz \
= { relative = 1\
5 }</code>), and\
 whether it drif\
ted; today's ste\
ps and\x0aBode are \
drawn over the b\
irth certificate\
's, and <b>Save \
PDF\xe2\x80\xa6</b> write\
s the drift repo\
rt.\x0aWithout an e\
nd-of-line test \
in the history i\
t says how to ma\
ke one and moves\
 nothing\x0a(comman\
d line: <code>pr\
m9tool --signatu\
re --device ID -\
-report drift.pd\
f</code>).</li>\x0a\
</ul>\x0a\x0a<h2>The a\
cceptance profil\
e (TOML)</h2>\x0a<p\
>Empty: the buil\
t-in profile. A \
file sets what d\
iffers from it; \
every key may be\
 left out.\x0a<code\
>[test]</code> a\
nd <code>[limits\
]</code> are for\
 the position lo\
op;\x0a<code>[proce\
ss.test]</code> \
and <code>[proce\
ss.limits]</code\
> for the E04 pr\
ocess loop, whos\
e\x0aown defaults a\
re 1.5 s step wi\
ndows, a sweep f\
rom 0.2 to 20 Hz\
, rise time \xe2\x89\xa4 \
0.4 s, settling\x0a\
time \xe2\x89\xa4 0.8 s a\
nd \xe2\x88\x923 dB \xe2\x89\xa5 0\
.8 Hz. A limit i\
s <code>{ min = \
\xe2\x80\xa6 }</code>,\x0a<c\
ode>{ max = \xe2\x80\xa6 \
}</code> or both\
.</p>\x0a<pre>\x0aname\
 = \x22PRM9-06 end \
of line\x22\x0a[test]\x0a\
step_amplitudes_\
pct = [5, 25, 90\
]\x0astep_duration_\
s = 0.15\x0astatic_\
period_s = 20\x0a[l\
imits]\x0astep_over\
shoot_pct = { ma\
x = 15 }\x0astep_ri\
se_s = { max = 0\
.03 }\x0abode_bandw\
idth_hz = { min \
= 15 }\x0astatic_hy\
steresis_pct = {\
 max = 2 }\x0a\x0a[pro\
cess.test]      \
# E04 in control\
 mode 4\x0astep_dur\
ation_s = 2.0\x0a[p\
rocess.limits]\x0as\
tep_rise_s = { m\
ax = 0.5 }\x0astep_\
settling_s = { m\
ax = 1.0 }\x0aflow_\
gain = { min = 3\
 }\x0a</pre>\x0a<p>Fig\
ures: step_overs\
hoot_pct, step_r\
ise_s, step_sett\
ling_s, bode_ban\
dwidth_hz,\x0abode_\
phase90_hz, stat\
ic_gain, static_\
hysteresis_pct, \
static_linearity\
_pct,\x0astatic_dea\
d_band_pct, flow\
_gain, flow_dead\
_band_pct. An un\
known key or a w\
rong value is\x0are\
fused with the f\
ile and the key \
named.</p>\x0a<p>Th\
e oscilloscope's\
 <b>Step respons\
e</b> tab measur\
es overshoot, ri\
se and settling \
time of\x0aany step\
 it shows.</p>\x0a<\
/body>\x0a</html>\x0a\
\x00\x00\x06\xe1\
<\
!DOCTYPE html>\x0a<\
html lang=\x22de\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>Parameters\xc3\xa4t\
ze vergleichen</\
title></head>\x0a<b\
ody>\x0a<p><a href=\
\x22help_de.html\x22>H\
ilfe zu prm9tool\
</a></p>\x0a<h1>Par\
ameters\xc3\xa4tze ver\
gleichen</h1>\x0a<p\
>Die Vergleichsa\
nsicht zeigt zwe\
i Parameters\xc3\xa4tz\
e nebeneinander \
in Anzeigeeinhei\
ten, dazu die\x0aWe\
rkseinstellungen\
 als dritte Spal\
te. Fett gedruck\
te Werte untersc\
heiden sich.</p>\
\x0a<ul>\x0a<li>Datei \
\xe2\x86\x92 <b>Mit Datei\
 vergleichen\xe2\x80\xa6<\
/b>: das Dokumen\
t gegen eine <co\
de>*.prm</code>-\
Datei\x0a(der Dialo\
g \xc3\xb6ffnet den zu\
letzt benutzten \
Ordner).</li>\x0a<l\
i>Ventil \xe2\x86\x92 <b>\
Mit Ventil vergl\
eichen</b> (onli\
ne): das Dokumen\
t gegen das, was\
 das Ventil\x0agera\
de enth\xc3\xa4lt.</li\
>\x0a<li>Beim Onlin\
e-Gehen mit eine\
m abweichenden D\
okument: <b>Je P\
arameter w\xc3\xa4hlen\
\xe2\x80\xa6</b>.</li>\x0a<l\
i>Ventil \xe2\x86\x92 Ver\
lauf: zwei Eintr\
\xc3\xa4ge w\xc3\xa4hlen, <b\
>Die zwei gew\xc3\xa4h\
lten Eintr\xc3\xa4ge v\
ergleichen</b>.<\
/li>\x0a</ul>\x0a<h2>W\
erte zur\xc3\xbcckschr\
eiben</h2>\x0a<ol>\x0a\
<li>Kreuzen Sie \
in jeder Zeile d\
en gew\xc3\xbcnschten \
Wert an (in der \
Spalte der Seite\
, von der er\x0akom\
mt), oder nehmen\
 Sie <b>Alle ang\
ezeigten Werte v\
on \xe2\x80\xa6 ankreuzen\
</b> f\xc3\xbcr die an\
gezeigten\x0aZeilen\
.</li>\x0a<li>Dr\xc3\xbcc\
ken Sie die Scha\
ltfl\xc3\xa4che, die s\
agt, wohin die W\
erte gehen: <b>\xe2\
\x80\xa6 angekreuzte W\
erte in\x0adas Vent\
il schreiben</b>\
 (ein Hochladen \
genau dieser Wer\
te: geschrieben,\
 zur\xc3\xbcckgelesen,\
\x0averglichen, ges\
peichert) oder <\
b>\xe2\x80\xa6 angekreuzt\
e Werte in das D\
okument \xc3\xbcberneh\
men</b> (ein\x0aR\xc3\xbc\
ckg\xc3\xa4ngig-Schrit\
t). Die Zeile \xc3\xbc\
ber der Tabelle \
sagt, welche Spa\
lte zu welcher S\
chaltfl\xc3\xa4che\x0ageh\
\xc3\xb6rt; eine Schal\
tfl\xc3\xa4che bleibt \
grau, bis etwas \
angekreuzt ist.<\
/li>\x0a</ol>\x0a<p>Fi\
lter: nur Unters\
chiede, ein Bloc\
k des Ablaufdiag\
ramms, die Basis\
- oder Expertens\
tufe.\x0aParameter,\
 die eine Ventil\
variante nicht h\
at, erscheinen a\
ls \xe2\x80\x9e\xe2\x80\x94\xe2\x80\x9c und\
 lassen sich nic\
ht\x0aw\xc3\xa4hlen.</p>\x0a\
</body>\x0a</html>\x0a\
\
\x00\x00 _\
<\
!DOCTYPE html>\x0a<\
html lang=\x22en\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>prm9tool help\
</title></head>\x0a\
<body>\x0a<h1>prm9t\
ool</h1>\x0a<p>prm9\
tool sets the pa\
rameters of PRM9\
 proportional di\
rectional valves\
 with integrated\
\x0adigital electro\
nics, over USB o\
r on the built-i\
n emulated valve\
. The valve's ow\
n manual\x0a(chapte\
r 8) describes t\
he parameters; t\
his page describ\
es the program.<\
/p>\x0a\x0a<p><b>More \
pages:</b> <a hr\
ef=\x22can_en.html\x22\
>CAN bus and CAN\
open</a> \xc2\xb7 <a h\
ref=\x22tuning_en.h\
tml\x22>Tuning and \
characterization\
</a> \xc2\xb7 <a href=\
\x22compare_en.html\
\x22>Compare parame\
ter sets</a> \xc2\xb7 \
<a href=\x22history\
_en.html\x22>Histor\
y of a valve</a>\
. In a window, <\
b>F1</b> opens t\
he page about it\
.</p>\x0a\x0a<h2>Start\
ing</h2>\x0a<ul>\x0a<l\
i><code>prm9tool\
</code> opens th\
e window with a \
new parameter se\
t.</li>\x0a<li><cod\
e>prm9tool FILE.\
prm</code> opens\
 a parameter fil\
e.</li>\x0a<li><cod\
e>prm9tool --emu\
lator [TYPEKEY[:\
SERIAL]]</code> \
starts online wi\
th an emulated v\
alve\x0a(default ty\
pe key <code>PRM\
9-06.3Z11/30-24E\
02S02-CA</code>)\
.</li>\x0a</ul>\x0a\x0a<h\
2>The window</h2\
>\x0a<p>Main menu, \
toolbar, main ar\
ea and status ba\
r. The status ba\
r shows the comm\
unication mode,\x0a\
the valve state \
(<i>ok</i> or th\
e active error),\
 the firmware ve\
rsion, the type \
key and the\x0afile\
 name; <b>*</b> \
marks unsaved ch\
anges; last the \
access level. Th\
e mode reads CON\
NECTING\x0awhile a \
valve just conne\
cted is compared\
 with the parame\
ter set, and ONL\
INE once they ag\
ree.</p>\x0a<p>The \
main area shows \
one of three vie\
ws: the <b>flow \
diagram</b> (cli\
ck a block to se\
t its\x0aparameters\
, click a red me\
asuring point to\
 watch it in the\
 oscilloscope), \
the\x0a<b>parameter\
 list</b> (doubl\
e-click a row to\
 change the valu\
e; values that d\
iffer from the\x0af\
actory defaults \
are highlighted;\
 search and \xe2\x80\x9cM\
odified only\xe2\x80\x9d \
filter the list)\
 and the\x0a<b>osci\
lloscope</b> (on\
line only, at mo\
st three measuri\
ng points).</p>\x0a\
\x0a<h2>Access leve\
ls</h2>\x0a<p><b>Ba\
sic</b> shows th\
e basic settings\
; at Basic level\
 the four ramps \
are set together\
.\x0a<b>Expert</b> \
adds the control\
lers, the linear\
izations and the\
 external-sensor\
 settings and\x0ais\
 protected by a \
password. The pa\
ssword as delive\
red is <code>exp\
ert</code>; chan\
ge it at\x0aExpert \
level with View \
\xe2\x86\x92 Access level\
 \xe2\x86\x92 Change Expe\
rt password. The\
 program keeps o\
nly a\x0asalted has\
h of it.</p>\x0a<p>\
The access level\
s guard against \
accidental chang\
es, not against \
someone who can \
edit the\x0aprogram\
's settings: rem\
oving the entry \
<code>access/exp\
ert_password</co\
de> from the set\
tings\x0abrings bac\
k the delivered \
password. A para\
meter file carri\
es every value w\
hatever the leve\
l:\x0aat Basic leve\
l, sending a doc\
ument whose Expe\
rt-level values \
differ from the \
valve's asks\x0afir\
st.</p>\x0a\x0a<h2>Onl\
ine and offline<\
/h2>\x0a<p>Communic\
ation \xe2\x86\x92 HID co\
nfiguration list\
s the valves con\
nected over USB \
and the emulated\
\x0avalves; add an \
emulated valve w\
ith its type key\
 and serial numb\
er. Communicatio\
n \xe2\x86\x92 Online\x0amod\
e connects. A do\
cument read from\
 another valve (\
another serial n\
umber) is named \
first: go on wit\
h it, or go offl\
ine. If the open\
 parameter set d\
iffers from the \
valve's, the pro\
gram lists the\x0ad\
ifferences and a\
sks whether to t\
ake the valve's \
values, send the\
 document's valu\
es\x0a(upload) or c\
ancel. Taking th\
e values of a va\
lve of another t\
ype makes the do\
cument a new, un\
saved one (its f\
ile keeps what i\
t held); a docum\
ent uploaded to \
a valve, or agre\
eing with it, is\
 that valve's fr\
om then on (SNV,\
 and no question\
 when going onli\
ne with it again\
). Online, every\
 change goes to \
the valve at onc\
e and into the d\
ocument;\x0aoffline\
, into the docum\
ent only.</p>\x0a<p\
><b>When the val\
ve drops off</b>\
 (a pulled USB c\
able, a power cy\
cle, a CAN bus-o\
ff, a restart\x0ath\
at does not come\
 back), the prog\
ram goes offline\
, keeps every va\
lue and looks fo\
r the valve\x0aby i\
tself: the statu\
s bar reads <i>M\
ode: RECONNECTIN\
G\xe2\x80\xa6 3 s</i>. It\
 looks on the sa\
me link \xe2\x80\x94 over\
\x0aCAN also at ano\
ther node ID, if\
 the serial numb\
er (0x1018/4) sa\
ys it is the sam\
e valve. When\x0ath\
e valve is back \
it reads it and \
compares it with\
 the document as\
 on going online\
\x0a(<i>Back online\
</i> when they a\
gree); nothing i\
s written to the\
 valve without y\
ou: values\x0achang\
ed online that t\
he valve lost in\
 a power cycle a\
re offered in th\
e differences di\
alog, not\x0asent. \
A tuning test cu\
t off by the lin\
k writes back wh\
at it had change\
d as soon as the\
 valve\x0ais back, \
and says so. The\
 oscilloscope re\
cords on; the se\
tpoint generator\
 and a tuning te\
st\x0astay stopped \
until you start \
them (over CAN t\
he reception dea\
dline a cut-off \
generator had se\
t\x0ain the valve i\
s put back when \
it is back, and \
the status bar s\
ays so). A bus-o\
ff of your CAN\x0aa\
dapter is named \
in the status ba\
r; the valve is \
found again once\
 the adapter is \
back on the\x0abus.\
 An upload that \
was cut off repo\
rts what happene\
d and what the v\
alve holds; it\x0ai\
s not resumed. A\
nother valve (an\
other serial num\
ber) where the l\
ost one was is a\
 new valve:\x0athe \
program says so \
and does not con\
nect to it by it\
self. Going onli\
ne or offline yo\
urself\x0astops the\
 search. With an\
 emulated valve,\
 Valve \xe2\x86\x92 Emula\
ted valve \xe2\x86\x92 <b\
>Pull the USB ca\
ble</b>\x0aand <b>P\
lug the USB cabl\
e back in</b> sh\
ow it.</p>\x0a<p>Va\
lues changed onl\
ine are active i\
n the valve but \
not yet stored: \
going offline of\
fers to\x0astore th\
em, and Valve \xe2\x86\
\x92 <b>Store in va\
lve</b> stores t\
hem at once (wha\
t the valve work\
s with\x0abecomes w\
hat it starts wi\
th; recorded in \
the history). <b\
>Upload to valve\
</b> writes all \
values, reads th\
em back, compare\
s and stores\x0athe\
m; nothing is st\
ored unless ever\
y value was veri\
fied. Before the\
 first upload to\
 a valve\x0athe pro\
gram saves a bac\
kup of the valve\
's own parameter\
s in the user da\
ta folder\x0a(<code\
>backups/&lt;ser\
ial&gt;/</code>)\
.</p>\x0a<p><b>Rest\
art valve</b> an\
d <b>Restore fac\
tory values</b> \
are allowed only\
 with the\x0ahydrau\
lics disconnecte\
d; the program a\
sks you to confi\
rm this.</p>\x0a<p>\
Valve \xe2\x86\x92 <b>Ver\
ify by restart\xe2\x80\
\xa6</b> (after an \
upload, while th\
e same valve sta\
ys online)\x0aresta\
rts the valve \xe2\x80\
\x94 after the same\
 hydraulics conf\
irmation \xe2\x80\x94 and\
 reads its param\
eters back:\x0athe \
status bar says \
\xe2\x80\x9c\xe2\x80\xa6 read back\
 unchanged \xe2\x80\xa6: \
verified after a\
 restart\xe2\x80\x9d, or \
a message lists\x0a\
each value the v\
alve did not kee\
p (expected \xe2\x86\x92 \
read back), and \
the history reco\
rds the outcome.\
\x0aThe upload's ow\
n message says h\
ow the valve kep\
t the values: \xe2\x80\
\x9cstored with 0x1\
010\xe2\x80\x9d, or over\x0a\
CANopen on a val\
ve without a sto\
re command \xe2\x80\x9cke\
pt by the valve \
as written (it h\
as no store\x0acomm\
and)\xe2\x80\x9d. Values \
changed online a\
nd not stored ye\
t must be stored\
 first (a restar\
t would\x0alose the\
m). If the valve\
 does not come b\
ack, the program\
 goes offline an\
d says what the \
valve\x0aholds as f\
ar as known; the\
 document keeps \
every value.</p>\
\x0a\x0a<h2>Files</h2>\
\x0a<p>Parameter fi\
les (<code>*.prm\
</code>) are tex\
t files. Open, S\
ave, Save As, th\
e recent\x0afiles a\
nd drag and drop\
 work as usual; \
the program asks\
 before unsaved \
changes are lost\
.\x0aEvery change c\
an be undone (Ct\
rl+Z) and redone\
 (Ctrl+Y). File \
\xe2\x86\x92 Print and Fi\
le \xe2\x86\x92 Export PD\
F\x0aproduce a para\
meter record wit\
h type key, seri\
al number, firmw\
are, file, date,\
 access level,\x0at\
he flow diagram \
and every parame\
ter with its uni\
t. Values change\
d since the file\
 was saved\x0aare m\
arked <b>*</b> a\
nd the file line\
 says so; every \
page names the t\
ype key and seri\
al\x0anumber and ca\
rries its page n\
umber; the last \
page has a line \
for date, name a\
nd\x0asignature.</p\
>\x0a<p><b>Back up \
a valve</b>: go \
online, Valve \xe2\x86\
\x92 Download from \
valve, then File\
 \xe2\x86\x92 <b>Save bac\
kup\x0acopy\xe2\x80\xa6</b> \
(proposed name: \
type key, serial\
 number, date an\
d time). The cop\
y is written and\
\x0athe open docume\
nt stays what it\
 was: later chan\
ges are saved in\
to the document'\
s own file,\x0aneve\
r into the backu\
p. Save As, by c\
ontrast, makes t\
he new file the \
open document.</\
p>\x0a\x0a<h2>Keyboard\
</h2>\x0a<table>\x0a<t\
r><td>Ctrl+O / C\
trl+S / Ctrl+Shi\
ft+S</td><td>Ope\
n / Save / Save \
As</td></tr>\x0a<tr\
><td>Ctrl+Z / Ct\
rl+Y</td><td>Und\
o / Redo</td></t\
r>\x0a<tr><td>Ctrl+\
P / Ctrl+E</td><\
td>Print / Expor\
t PDF</td></tr>\x0a\
<tr><td>Ctrl+1 /\
 Ctrl+2 / Ctrl+3\
 / Ctrl+4</td><t\
d>Flow diagram /\
 Parameter list \
/ Oscilloscope /\
 CANopen window<\
/td></tr>\x0a<tr><t\
d>F5 / Shift+F5<\
/td><td>Online /\
 Offline</td></t\
r>\x0a<tr><td>Ctrl+\
U / Ctrl+D</td><\
td>Upload to val\
ve / Download fr\
om valve</td></t\
r>\x0a<tr><td>Ctrl+\
T / Ctrl+I / Ctr\
l+H</td><td>Valv\
e selection / Va\
lve status / HID\
 configuration</\
td></tr>\x0a</table\
>\x0a<p><b>Scripts \
and test benches\
</b>: the valve \
from Python and \
shell scripts, <\
a href=\x22scriptin\
g_en.html\x22>on th\
is page</a> (in \
English).</p>\x0a</\
body>\x0a</html>\x0a\
\x00\x00\x0e\x83\
<\
!DOCTYPE html>\x0a<\
html lang=\x22en\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>CAN bus and C\
ANopen</title></\
head>\x0a<body>\x0a<p>\
<a href=\x22help_en\
.html\x22>prm9tool \
help</a></p>\x0a<h1\
>CAN bus and CAN\
open</h1>\x0a<p>A -\
CA valve also ta\
lks CANopen (man\
ual chapter 7). \
prm9tool is then\
 the CANopen mas\
ter,\x0athrough any\
 CAN adapter pyt\
hon-can supports\
 (PEAK, Kvaser, \
IXXAT, Vector, C\
ANable/slcan,\x0aSo\
cketCAN).</p>\x0a<h\
2>Going online o\
ver CAN</h2>\x0a<ol\
>\x0a<li>Communicat\
ion \xe2\x86\x92 <b>CAN b\
us\xe2\x80\xa6</b>: choos\
e the interface,\
 the channel and\
 the bit rate,\x0at\
hen <b>Search th\
e bus</b>. Every\
 node that answe\
rs is listed wit\
h its NMT state,\
 heartbeat\x0aand l\
ast EMCY; nodes \
that are not PRM\
9 valves cannot \
be chosen.</li>\x0a\
<li>Choose the v\
alve and press O\
K: the program g\
oes online with \
it (<code>can:NO\
DE</code>).\x0aA re\
al valve does no\
t tell its full \
type key: type t\
he one on its la\
bel; it is remem\
bered\x0aper serial\
 number.</li>\x0a</\
ol>\x0a<h2>Commissi\
oning</h2>\x0a<p>A \
-CA valve as del\
ivered waits for\
 its master: NMT\
 pre-operational\
, device state I\
NIT; it\x0adoes not\
 follow its setp\
oint. Valve \xe2\x86\x92 \
<b>Valve status<\
/b>, group Commi\
ssioning: press\x0a\
<b>NMT start</b>\
, then <b>Enable\
</b> (control wo\
rd 08h \xe2\x86\x92 09h \xe2\
\x86\x92 0Bh \xe2\x86\x92 0Fh).\
 The line below\x0a\
the buttons says\
 what is still m\
issing. Disable \
and NMT stop tak\
e it back.</p>\x0a<\
h2>Objects and c\
onfiguration</h2\
>\x0a<ul>\x0a<li>View \
\xe2\x86\x92 <b>Object di\
ctionary\xe2\x80\xa6</b> \
reads every obje\
ct; type in the \
search line to f\
ind an\x0aindex, a \
name or a value.\
 At Expert level\
 a double-click \
writes a writabl\
e object.</li>\x0a<\
li>View \xe2\x86\x92 <b>C\
ANopen window</b\
>: node ID, bit \
rate and termina\
tor. The valve r\
eads its\x0arotary \
switches at powe\
r-up; a changed \
node ID or bit r\
ate takes effect\
 after a restart\
, and\x0aprm9tool f\
inds the valve a\
t its new addres\
s after Valve \xe2\x86\
\x92 Restart valve.\
</li>\x0a<li>File \xe2\
\x86\x92 <b>Export DCF\
\xe2\x80\xa6</b> saves th\
e valve's config\
uration for a PL\
C configurator.<\
/li>\x0a<li>Valve \xe2\
\x86\x92 <b>Store in v\
alve</b> makes t\
he values the va\
lve works with p\
ermanent (object\
\x0a0x1010, or the \
valve's own way \
where it lacks i\
t).</li>\x0a<li>A v\
alve without obj\
ect 0x1010 (the \
manual's object \
list has none) k\
eeps every value\
 as it\x0ais writte\
n: the upload wr\
ites in an order\
 that never leav\
es a combination\
 the rules refus\
e,\x0areads everyth\
ing back and say\
s \xe2\x80\x9ckept by the\
 valve as writte\
n (it has no sto\
re command)\xe2\x80\x9d.\x0a\
Valve \xe2\x86\x92 <b>Ver\
ify by restart\xe2\x80\
\xa6</b> then resta\
rts it (NMT rese\
t node, hydrauli\
cs disconnected)\
\x0aand reads back \
that it kept the\
m: \xe2\x80\x9cverified a\
fter a restart\xe2\x80\
\x9d.</li>\x0a</ul>\x0a<p\
>The oscilloscop\
e takes the actu\
al position from\
 TPDO1; the setp\
oint generator a\
nd the tuning\x0ate\
sts send the set\
point in RPDO1, \
as a PLC does.</\
p>\x0a<h2>Recording\
 and reading the\
 bus</h2>\x0a<p>Com\
munication \xe2\x86\x92 <\
b>CAN bus\xe2\x80\xa6</b>\
 \xe2\x86\x92 <b>Record\xe2\x80\
\xa6</b> writes eve\
ry frame of the \
bus, with its\x0ati\
me, into a trace\
 file (ASC, BLF,\
 TRC or candump \
log); the record\
ing goes on besi\
de whatever\x0athe \
program does on \
the bus (an uplo\
ad, a test) unti\
l <b>Stop record\
ing</b>. Communi\
cation \xe2\x86\x92\x0a<b>CA\
N trace\xe2\x80\xa6</b> o\
pens such a file\
, also one recor\
ded by PCAN-View\
, CANalyzer or\x0a<\
code>candump</co\
de>, and reads i\
t in words: NMT \
commands and sta\
tes per node, SD\
O transfers\x0awith\
 the object's na\
me, its value in\
 display units a\
nd an abort in w\
ords, PDOs by th\
e mapping\x0ain for\
ce at that momen\
t, control and s\
tatus words as s\
tate changes, EM\
CY by the manual\
's\x0aerror table, \
SYNC period and \
jitter, LSS. Fil\
ter by node and \
kind; the list o\
f incidents (a\x0an\
ode that went si\
lent, an EMCY, a\
 left DEVICE_MOD\
E_ACTIVE, an SDO\
 abort) selects \
their frame.\x0aOn \
the command line\
: <code>prm9tool\
 --record trace.\
asc</code>, <cod\
e>prm9tool --dec\
ode\x0atrace.asc</c\
ode> (<code>--js\
on</code>, <code\
>--csv</code>, <\
code>--fail-on-i\
ncident</code>) \
and\x0a<code>prm9to\
ol --replay trac\
e.asc</code>.</p\
>\x0a</body>\x0a</html\
>\x0a\
\x00\x00\x07\xbb\
<\
!DOCTYPE html>\x0a<\
html lang=\x22en\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>Scripts and t\
est benches</tit\
le></head>\x0a<body\
>\x0a<p><a href=\x22he\
lp_en.html\x22>prm9\
tool help</a></p\
>\x0a<h1>Scripts an\
d test benches</\
h1>\x0a<p>Test benc\
hes, end-of-line\
 stations and no\
tebooks drive a \
valve from Pytho\
n with the\x0a<code\
>prm9tool</code>\
 package, withou\
t the window and\
 without Qt. It \
uses the same li\
nks, the\x0asame up\
load (write ever\
y value, read ev\
ery one back, co\
mpare, store) an\
d the same histo\
ry as\x0athe progra\
m.</p>\x0a<pre>\x0aimp\
ort prm9tool\x0a\x0awi\
th prm9tool.conn\
ect(\x22usb:/dev/hi\
draw0\x22) as valve\
:   # or \x22emulat\
or:TYPEKEY:SERIA\
L\x22, \x22can:10\x22\x0a   \
 print(valve.inf\
o.type_key, valv\
e.info.serial)\x0a \
   valve[\x22LIMTA\x22\
] = 1800        \
          # mA: \
checked, written\
, read back\x0a    \
result = valve.u\
pload(prm9tool.r\
ead_prm(\x22release\
d.prm\x22))\x0a    pri\
nt(result.stored\
)\x0a    data = val\
ve.capture([\x22dem\
and\x22, \x22position_\
actual\x22], second\
s=1.0)\x0a</pre>\x0a<p\
><code>prm9tool.\
list_devices()</\
code> lists the \
valves (on a CAN\
 bus with\x0a<code>\
can_interface=\xe2\x80\
\xa6</code>, <code>\
can_channel=\xe2\x80\xa6<\
/code>). A valve\
 also stores, re\
stores the\x0afacto\
ry values, resta\
rts (only with <\
code>confirm_hyd\
raulics_off=True\
</code>), takes \
NMT\x0acommands, is\
 enabled, runs t\
he setpoint gene\
rator and the en\
d-of-line test. \
The measuring\x0apo\
ints of <code>ca\
pture</code> are\
 those of the os\
cilloscope (<cod\
e>demand</code>,\
\x0a<code>position_\
actual</code>, <\
code>current_a</\
code> \xe2\x80\xa6).</p>\x0a\
<h2>Shell script\
s</h2>\x0a<pre>\x0aprm\
9tool --device 4\
711 --set LIMTA=\
1800 DYNFREQ=120\
 --store\x0aprm9too\
l --device 4711 \
--get LIMTA DYNF\
REQ --json\x0aprm9t\
ool --list-devic\
es --json\x0a</pre>\
\x0a<p><code>--set<\
/code> checks ev\
ery value before\
 it writes the f\
irst and reads e\
ach back; withou\
t\x0a<code>--store<\
/code> the value\
s are not stored\
. Exit code 0: d\
one, 1: the valv\
e refused a valu\
e,\x0a2: a wrong mn\
emonic or value \
(nothing written\
), 4: no such va\
lve, 6: no answe\
r.</p>\x0a<p>Every \
call, the list o\
f measuring poin\
ts and the JSON:\
 <code>docs/api.\
md</code> in the\
\x0asource distribu\
tion.</p>\x0a</body\
>\x0a</html>\x0a\
\x00\x00\x01\xc2\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x223\x22 y=\
\x222.5\x22 width=\x2210\x22\
 height=\x228\x22 rx=\x22\
1.5\x22 fill=\x22#8a96\
a3\x22 stroke=\x22#4a5\
25c\x22/><rect x=\x225\
\x22 y=\x224.5\x22 width=\
\x226\x22 height=\x223\x22 f\
ill=\x22#e7ecf1\x22/><\
path d=\x22M18.5 18\
H15V8\x22 fill=\x22non\
e\x22 stroke=\x22#e07b\
12\x22 stroke-width\
=\x222\x22/><path d=\x22M\
11 9h8l-4-5z\x22 fi\
ll=\x22#e07b12\x22 tra\
nsform=\x22translat\
e(0 1)\x22/><rect x\
=\x224\x22 y=\x2216\x22 widt\
h=\x2210\x22 height=\x226\
\x22 rx=\x221\x22 fill=\x22#\
f4f4f4\x22 stroke=\x22\
#5a6470\x22/></svg>\
\x0a\
\x00\x00\x01\xa2\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x226\x22 y=\
\x222.5\x22 width=\x2212\x22\
 height=\x227\x22 fill\
=\x22#f4f4f4\x22 strok\
e=\x22#5a6470\x22/><re\
ct x=\x222.5\x22 y=\x229\x22\
 width=\x2219\x22 heig\
ht=\x229\x22 rx=\x221.5\x22 \
fill=\x22#8a96a3\x22 s\
troke=\x22#4a525c\x22/\
><rect x=\x226\x22 y=\x22\
14.5\x22 width=\x2212\x22\
 height=\x227\x22 fill\
=\x22#ffffff\x22 strok\
e=\x22#5a6470\x22/><pa\
th d=\x22M8 17h8M8 \
19h6\x22 stroke=\x22#5\
a6470\x22/><circle \
cx=\x2218.5\x22 cy=\x2211\
.5\x22 r=\x221\x22 fill=\x22\
#7bd88f\x22/></svg>\
\x0a\
\x00\x00\x00\xf9\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><path d=\x22M18.4\
 8.5A7.5 7.5 0 1\
 0 19.5 13\x22 fill\
=\x22none\x22 stroke=\x22\
#d9443a\x22 stroke-\
width=\x222.4\x22 stro\
ke-linecap=\x22roun\
d\x22/><path d=\x22M14\
.5 8.8h5.6V3.2z\x22\
 fill=\x22#d9443a\x22/\
></svg>\x0a\
\x00\x00\x01\xb5\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x221.5\x22 \
y=\x228.5\x22 width=\x226\
\x22 height=\x227\x22 fil\
l=\x22#e7ecf1\x22 stro\
ke=\x22#4a525c\x22/><r\
ect x=\x229.5\x22 y=\x228\
.5\x22 width=\x226\x22 he\
ight=\x227\x22 fill=\x22#\
e7ecf1\x22 stroke=\x22\
#4a525c\x22/><rect \
x=\x2217\x22 y=\x228.5\x22 w\
idth=\x225.5\x22 heigh\
t=\x227\x22 fill=\x22#e7e\
cf1\x22 stroke=\x22#4a\
525c\x22/><path d=\x22\
M7.5 12h2M15.5 1\
2h1.5\x22 stroke=\x22#\
2f7fd6\x22 stroke-w\
idth=\x221.6\x22/><cir\
cle cx=\x228.5\x22 cy=\
\x2212\x22 r=\x221.3\x22 fil\
l=\x22#d9443a\x22/></s\
vg>\x0a\
\x00\x00\x01>\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x222.5\x22 \
y=\x224.5\x22 width=\x221\
9\x22 height=\x2215\x22 r\
x=\x222\x22 fill=\x22#e7e\
cf1\x22 stroke=\x22#4a\
525c\x22/><circle c\
x=\x227\x22 cy=\x2212\x22 r=\
\x222.5\x22 fill=\x22#3db\
b5a\x22/><circle cx\
=\x2212\x22 cy=\x2212\x22 r=\
\x222.5\x22 fill=\x22#d94\
43a\x22/><circle cx\
=\x2217\x22 cy=\x2212\x22 r=\
\x222.5\x22 fill=\x22#f0a\
020\x22/></svg>\x0a\
\x00\x00\x01)\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><path d=\x22M3 12\
h5M16 12h5\x22 stro\
ke=\x22#2e9d47\x22 str\
oke-width=\x222.2\x22 \
stroke-linecap=\x22\
round\x22/><path d=\
\x22M8 7h4a5 5 0 0 \
1 0 10H8z\x22 fill=\
\x22#3dbb5a\x22 stroke\
=\x22#22753a\x22/><pat\
h d=\x22M16 9v6\x22 st\
roke=\x22#22753a\x22 s\
troke-width=\x222\x22/\
></svg>\x0a\
\x00\x00\x01\xcb\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x222\x22 y=\
\x228\x22 width=\x2220\x22 h\
eight=\x229\x22 rx=\x221\x22\
 fill=\x22#b8c1cb\x22 \
stroke=\x22#4a525c\x22\
/><rect x=\x227\x22 y=\
\x228\x22 width=\x2210\x22 h\
eight=\x229\x22 fill=\x22\
#e7ecf1\x22 stroke=\
\x22#4a525c\x22/><path\
 d=\x22M9 10.5l6 4M\
15 10.5l-6 4\x22 st\
roke=\x22#2f7fd6\x22 s\
troke-width=\x221.5\
\x22/><rect x=\x229\x22 y\
=\x222.5\x22 width=\x226\x22\
 height=\x225.5\x22 rx\
=\x221\x22 fill=\x22#3dbb\
5a\x22 stroke=\x22#227\
53a\x22/><path d=\x22M\
8 17v4M16 17v4\x22 \
stroke=\x22#4a525c\x22\
 stroke-width=\x222\
\x22/></svg>\x0a\
\x00\x00\x01\xc5\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><path d=\x22M2 7h\
20M2 17h20\x22 stro\
ke=\x22#4a525c\x22 str\
oke-width=\x221.8\x22/\
><path d=\x22M6 7v1\
0M12 7v10M18 7v1\
0\x22 stroke=\x22#8a96\
a3\x22 stroke-width\
=\x221.2\x22/><rect x=\
\x223.5\x22 y=\x229.5\x22 wi\
dth=\x225\x22 height=\x22\
5\x22 fill=\x22#e07b12\
\x22 stroke=\x22#8c4a0\
8\x22/><rect x=\x229.5\
\x22 y=\x229.5\x22 width=\
\x225\x22 height=\x225\x22 f\
ill=\x22#2f7fd6\x22 st\
roke=\x22#1d4f86\x22/>\
<rect x=\x2215.5\x22 y\
=\x229.5\x22 width=\x225\x22\
 height=\x225\x22 fill\
=\x22#3dbb5a\x22 strok\
e=\x22#22753a\x22/></s\
vg>\x0a\
\x00\x00\x02\x80\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2264\
\x22 height=\x2264\x22 vi\
ewBox=\x220 0 64 64\
\x22><rect x=\x224\x22 y=\
\x2222\x22 width=\x2256\x22 \
height=\x2224\x22 rx=\x22\
3\x22 fill=\x22#b8c1cb\
\x22 stroke=\x22#39424\
c\x22 stroke-width=\
\x222\x22/><rect x=\x2218\
\x22 y=\x2222\x22 width=\x22\
28\x22 height=\x2224\x22 \
fill=\x22#e7ecf1\x22 s\
troke=\x22#39424c\x22 \
stroke-width=\x222\x22\
/><path d=\x22M23 2\
8l18 12M41 28L23\
 40\x22 stroke=\x22#2f\
7fd6\x22 stroke-wid\
th=\x223\x22/><rect x=\
\x2222\x22 y=\x224\x22 width\
=\x2220\x22 height=\x2216\
\x22 rx=\x223\x22 fill=\x22#\
3dbb5a\x22 stroke=\x22\
#22753a\x22 stroke-\
width=\x222\x22/><text\
 x=\x2232\x22 y=\x2216\x22 f\
ont-family=\x22sans\
-serif\x22 font-siz\
e=\x229\x22 font-weigh\
t=\x22bold\x22 text-an\
chor=\x22middle\x22 fi\
ll=\x22#ffffff\x22>PRM\
9</text><path d=\
\x22M20 46v12M44 46\
v12\x22 stroke=\x22#39\
424c\x22 stroke-wid\
th=\x224\x22/></svg>\x0a\
\x00\x00\x01=\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x222.5\x22 \
y=\x223.5\x22 width=\x221\
9\x22 height=\x2217\x22 f\
ill=\x22#ffffff\x22 st\
roke=\x22#4a525c\x22/>\
<rect x=\x222.5\x22 y=\
\x223.5\x22 width=\x2219\x22\
 height=\x224\x22 fill\
=\x22#8a96a3\x22 strok\
e=\x22#4a525c\x22/><pa\
th d=\x22M2.5 11.5h\
19M2.5 15.5h19M9\
 7.5v13M16 7.5v1\
3\x22 stroke=\x22#8a96\
a3\x22/></svg>\x0a\
\x00\x00\x01\xa8\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x223\x22 y=\
\x222.5\x22 width=\x2210\x22\
 height=\x228\x22 rx=\x22\
1.5\x22 fill=\x22#8a96\
a3\x22 stroke=\x22#4a5\
25c\x22/><rect x=\x225\
\x22 y=\x224.5\x22 width=\
\x226\x22 height=\x223\x22 f\
ill=\x22#e7ecf1\x22/><\
path d=\x22M15 6h3.\
5v9\x22 fill=\x22none\x22\
 stroke=\x22#2f7fd6\
\x22 stroke-width=\x22\
2\x22/><path d=\x22M14\
.5 14h8l-4 5z\x22 f\
ill=\x22#2f7fd6\x22/><\
rect x=\x224\x22 y=\x2216\
\x22 width=\x2210\x22 hei\
ght=\x226\x22 rx=\x221\x22 f\
ill=\x22#f4f4f4\x22 st\
roke=\x22#5a6470\x22/>\
</svg>\x0a\
\x00\x00\x01\x94\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><path d=\x22M2 12\
h4M18 12h4\x22 stro\
ke=\x22#8a96a3\x22 str\
oke-width=\x222.2\x22 \
stroke-linecap=\x22\
round\x22/><path d=\
\x22M6 7.5h3a4.5 4.\
5 0 0 1 0 9H6z\x22 \
fill=\x22#b8c1cb\x22 s\
troke=\x22#6b7682\x22/\
><path d=\x22M18 7.\
5h-3a4.5 4.5 0 0\
 0 0 9h3z\x22 fill=\
\x22#b8c1cb\x22 stroke\
=\x22#6b7682\x22/><pat\
h d=\x22M10 19l4-14\
\x22 stroke=\x22#d9443\
a\x22 stroke-width=\
\x222\x22 stroke-linec\
ap=\x22round\x22/></sv\
g>\x0a\
\x00\x00\x01G\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x222\x22 y=\
\x223\x22 width=\x2220\x22 h\
eight=\x2216\x22 rx=\x221\
.5\x22 fill=\x22#26323\
8\x22 stroke=\x22#4a52\
5c\x22/><path d=\x22M4\
 14c2 0 2-7 4-7s\
2 9 4 9 2-6 4-6 \
2 3 4 3\x22 fill=\x22n\
one\x22 stroke=\x22#7b\
d88f\x22 stroke-wid\
th=\x221.6\x22/><path \
d=\x22M8 21h8\x22 stro\
ke=\x22#4a525c\x22 str\
oke-width=\x222\x22/><\
/svg>\x0a\
"

qt_resource_name = b"\
\x00\x05\
\x00o\xa6S\
\x00i\
\x00c\x00o\x00n\x00s\
\x00\x04\
\x00\x06\xec0\
\x00h\
\x00e\x00l\x00p\
\x00\x0b\
\x0a\xd7\xf3\x9c\
\x00c\
\x00a\x00n\x00_\x00d\x00e\x00.\x00h\x00t\x00m\x00l\
\x00\x0f\
\x04\xc4D\x1c\
\x00c\
\x00o\x00m\x00p\x00a\x00r\x00e\x00_\x00e\x00n\x00.\x00h\x00t\x00m\x00l\
\x00\x0f\
\x0f(y\xbc\
\x00h\
\x00i\x00s\x00t\x00o\x00r\x00y\x00_\x00d\x00e\x00.\x00h\x00t\x00m\x00l\
\x00\x0c\
\x07\xbc\x97\x9c\
\x00h\
\x00e\x00l\x00p\x00_\x00c\x00s\x00.\x00h\x00t\x00m\x00l\
\x00\x0f\
\x0fHy\xbc\
\x00h\
\x00i\x00s\x00t\x00o\x00r\x00y\x00_\x00c\x00s\x00.\x00h\x00t\x00m\x00l\
\x00\x0e\
\x02\xe4\x7f|\
\x00t\
\x00u\x00n\x00i\x00n\x00g\x00_\x00d\x00e\x00.\x00h\x00t\x00m\x00l\
\x00\x0f\
\x02\xb4D\x1c\
\x00c\
\x00o\x00m\x00p\x00a\x00r\x00e\x00_\x00c\x00s\x00.\x00h\x00t\x00m\x00l\
\x00\x0e\
\x03\x04\x7f|\
\x00t\
\x00u\x00n\x00i\x00n\x00g\x00_\x00c\x00s\x00.\x00h\x00t\x00m\x00l\
\x00\x0c\
\x07\xdc\x97\x9c\
\x00h\
\x00e\x00l\x00p\x00_\x00d\x00e\x00.\x00h\x00t\x00m\x00l\
\x00\x0f\
\x01xy\x9c\
\x00h\
\x00i\x00s\x00t\x00o\x00r\x00y\x00_\x00e\x00n\x00.\x00h\x00t\x00m\x00l\
\x00\x0b\
\x0a\xb7\xf3\x9c\
\x00c\
\x00a\x00n\x00_\x00c\x00s\x00.\x00h\x00t\x00m\x00l\
\x00\x0e\
\x04\xb4\x7f|\
\x00t\
\x00u\x00n\x00i\x00n\x00g\x00_\x00e\x00n\x00.\x00h\x00t\x00m\x00l\
\x00\x0f\
\x02\xd4D\x1c\
\x00c\
\x00o\x00m\x00p\x00a\x00r\x00e\x00_\x00d\x00e\x00.\x00h\x00t\x00m\x00l\
\x00\x0c\
\x09\xcc\x97\x9c\
\x00h\
\x00e\x00l\x00p\x00_\x00e\x00n\x00.\x00h\x00t\x00m\x00l\
\x00\x0b\
\x0c\xc7\xf3\x9c\
\x00c\
\x00a\x00n\x00_\x00e\x00n\x00.\x00h\x00t\x00m\x00l\
\x00\x11\
\x06\xaa\xc5\x9c\
\x00s\
\x00c\x00r\x00i\x00p\x00t\x00i\x00n\x00g\x00_\x00e\x00n\x00.\x00h\x00t\x00m\x00l\
\
\x00\x0a\
\x05x\xd4\xa7\
\x00u\
\x00p\x00l\x00o\x00a\x00d\x00.\x00s\x00v\x00g\
\x00\x09\
\x00W\xb5\xe7\
\x00p\
\x00r\x00i\x00n\x00t\x00.\x00s\x00v\x00g\
\x00\x0b\
\x08f\xcf\x87\
\x00r\
\x00e\x00s\x00t\x00a\x00r\x00t\x00.\x00s\x00v\x00g\
\x00\x0b\
\x08\xad\xb5\x07\
\x00d\
\x00i\x00a\x00g\x00r\x00a\x00m\x00.\x00s\x00v\x00g\
\x00\x0a\
\x0b\xcd\x0f\xc7\
\x00s\
\x00t\x00a\x00t\x00u\x00s\x00.\x00s\x00v\x00g\
\x00\x0a\
\x00J\x90\xa7\
\x00o\
\x00n\x00l\x00i\x00n\x00e\x00.\x00s\x00v\x00g\
\x00\x09\
\x03\xc8\xa3\xc7\
\x00v\
\x00a\x00l\x00v\x00e\x00.\x00s\x00v\x00g\
\x00\x0b\
\x06\x92P\x07\
\x00c\
\x00a\x00n\x00o\x00p\x00e\x00n\x00.\x00s\x00v\x00g\
\x00\x07\
\x08sZ\x07\
\x00a\
\x00p\x00p\x00.\x00s\x00v\x00g\
\x00\x0e\
\x0d\x86>'\
\x00p\
\x00a\x00r\x00a\x00m\x00e\x00t\x00e\x00r\x00s\x00.\x00s\x00v\x00g\
\x00\x0c\
\x08\x1a\x90\xa7\
\x00d\
\x00o\x00w\x00n\x00l\x00o\x00a\x00d\x00.\x00s\x00v\x00g\
\x00\x0b\
\x00\xaf\xc0\xa7\
\x00o\
\x00f\x00f\x00l\x00i\x00n\x00e\x00.\x00s\x00v\x00g\
\x00\x09\
\x06h\xa9\x87\
\x00s\
\x00c\x00o\x00p\x00e\x00.\x00s\x00v\x00g\
"

qt_resource_struct = b"\
\x00\x00\x00\x00\x00\x02\x00\x00\x00\x02\x00\x00\x00\x01\
\x00\x00\x00\x10\x00\x02\x00\x00\x00\x10\x00\x00\x00\x10\
\x00\x00\x00\x00\x00\x02\x00\x00\x00\x0d\x00\x00\x00\x03\
\x00\x00\x02\xb6\x00\x00\x00\x00\x00\x01\x00\x01\x22:\
\x00\x00\x02L\x00\x00\x00\x00\x00\x01\x00\x01\x1c\x9c\
\x00\x00\x03X\x00\x00\x00\x00\x00\x01\x00\x01,p\
\x00\x00\x02\xd0\x00\x00\x00\x00\x00\x01\x00\x01#g\
\x00\x00\x022\x00\x00\x00\x00\x00\x01\x00\x01\x1a\xd6\
\x00\x00\x03t\x00\x00\x00\x00\x00\x01\x00\x01.\x08\
\x00\x00\x02\xe8\x00\x00\x00\x00\x00\x01\x00\x01%6\
\x00\x00\x03:\x00\x00\x00\x00\x00\x01\x00\x01*\xc4\
\x00\x00\x02d\x00\x00\x00\x00\x00\x01\x00\x01\x1eB\
\x00\x00\x03\x04\x00\x00\x00\x00\x00\x01\x00\x01&\xff\
\x00\x00\x02\x80\x00\x00\x00\x00\x00\x01\x00\x01\x1f?\
\x00\x00\x02\x9c\x00\x00\x00\x00\x00\x01\x00\x01 \xf8\
\x00\x00\x03\x18\x00\x00\x00\x00\x00\x01\x00\x01)\x83\
\x00\x00\x01J\x00\x00\x00\x00\x00\x01\x00\x00\xadR\
\x00\x00\x00\xe6\x00\x00\x00\x00\x00\x01\x00\x00f\xe6\
\x00\x00\x01\xac\x00\x00\x00\x00\x00\x01\x00\x00\xddH\
\x00\x00\x00\xc4\x00\x00\x00\x00\x00\x01\x00\x00K^\
\x00\x00\x01\x0a\x00\x00\x00\x00\x00\x01\x00\x00mq\
\x00\x00\x01\x8a\x00\x00\x00\x00\x00\x01\x00\x00\xc4\x94\
\x00\x00\x00:\x00\x00\x00\x00\x00\x01\x00\x00\x10\x11\
\x00\x00\x02\x0a\x00\x00\x00\x00\x00\x01\x00\x01\x13\x17\
\x00\x00\x00\x82\x00\x00\x00\x00\x00\x01\x00\x00\x1e\xd7\
\x00\x00\x01,\x00\x00\x00\x00\x00\x01\x00\x00\x87\xd9\
\x00\x00\x01\xd0\x00\x00\x00\x00\x00\x01\x00\x00\xe4-\
\x00\x00\x01n\x00\x00\x00\x00\x00\x01\x00\x00\xb4\xfd\
\x00\x00\x00\x1e\x00\x00\x00\x00\x00\x01\x00\x00\x00\x00\
\x00\x00\x01\xee\x00\x00\x00\x00\x00\x01\x00\x01\x04\x90\
\x00\x00\x00^\x00\x00\x00\x00\x00\x01\x00\x00\x15\xff\
\x00\x00\x00\xa0\x00\x00\x00\x00\x00\x01\x00\x00B\xfc\
"

def qInitResources():
    QtCore.qRegisterResourceData(0x01, qt_resource_struct, qt_resource_name, qt_resource_data)

def qCleanupResources():
    QtCore.qUnregisterResourceData(0x01, qt_resource_struct, qt_resource_name, qt_resource_data)

qInitResources()
