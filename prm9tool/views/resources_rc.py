# Resource object code (Python 3)
# Created by: object code
# Created by: The Resource Compiler for Qt version 6.11.3
# WARNING! All changes made in this file will be lost!

from PySide6 import QtCore

qt_resource_data = b"\
\x00\x00\x137\
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
>\x0a\x0a<h2>Spu\xc5\xa1t\xc4\x9bn\
\xc3\xad</h2>\x0a<ul>\x0a<li\
><code>prm9tool<\
/code> otev\xc5\x99e o\
kno s nov\xc3\xbdm z\xc3\xa1\
znamem parametr\xc5\
\xaf.</li>\x0a<li><cod\
e>prm9tool SOUBO\
R.prm</code> ote\
v\xc5\x99e z\xc3\xa1znam par\
ametr\xc5\xaf.</li>\x0a<l\
i><code>prm9tool\
 --emulator [TYP\
OV\xc3\x9d_KL\xc3\x8d\xc4\x8c[:V\xc3\x9d\
ROBN\xc3\x8d_\xc4\x8c\xc3\x8dSLO]]\
</code> spust\xc3\xad \
program v re\xc5\xbeim\
u\x0aonline s emulo\
van\xc3\xbdm ventilem \
(v\xc3\xbdchoz\xc3\xad typov\
\xc3\xbd kl\xc3\xad\xc4\x8d <code>\
PRM9-06.3Z11/30-\
24E02S02-CA</cod\
e>).</li>\x0a</ul>\x0a\
\x0a<h2>Okno</h2>\x0a<\
p>Hlavn\xc3\xad menu, \
panel n\xc3\xa1stroj\xc5\xaf\
, hlavn\xc3\xad plocha\
 a stavov\xc3\xbd \xc5\x99\xc3\xa1\
dek. Stavov\xc3\xbd \xc5\x99\
\xc3\xa1dek zobrazuje \
re\xc5\xbeim\x0akomunikac\
e, stav elektron\
iky ventilu (<i>\
ok</i> nebo akti\
vn\xc3\xad chybu), ver\
zi firmware, typ\
ov\xc3\xbd\x0akl\xc3\xad\xc4\x8d a n\xc3\
\xa1zev souboru; <b\
>*</b> ozna\xc4\x8duje\
 neulo\xc5\xbeen\xc3\xa9 zm\xc4\
\x9bny.</p>\x0a<p>Hlav\
n\xc3\xad plocha zobra\
zuje jeden ze t\xc5\
\x99\xc3\xad n\xc3\xa1hled\xc5\xaf: <\
b>postupov\xc3\xbd dia\
gram</b> (kliknu\
t\xc3\xadm na blok\x0anas\
tav\xc3\xadte jeho par\
ametry, kliknut\xc3\
\xadm na \xc4\x8derven\xc3\xbd \
m\xc4\x9b\xc5\x99ic\xc3\xad bod je\
j zobraz\xc3\xadte v o\
sciloskopu),\x0a<b>\
seznam parametr\xc5\
\xaf</b> (dvojklike\
m na \xc5\x99\xc3\xa1dek zm\xc4\
\x9bn\xc3\xadte hodnotu; \
hodnoty odli\xc5\xa1n\xc3\
\xa9 od tov\xc3\xa1rn\xc3\xadho\
\x0anastaven\xc3\xad jsou\
 zv\xc3\xbdrazn\xc4\x9bny; h\
led\xc3\xa1n\xc3\xad a \xe2\x80\x9eJe\
n zm\xc4\x9bn\xc4\x9bn\xc3\xa9\xe2\x80\x9c \
seznam filtruj\xc3\xad\
) a <b>oscilosko\
p</b>\x0a(pouze v r\
e\xc5\xbeimu online, n\
ejv\xc3\xbd\xc5\xa1e t\xc5\x99i m\xc4\
\x9b\xc5\x99ic\xc3\xad body).</\
p>\x0a\x0a<h2>\xc3\x9arovn\xc4\x9b\
 opr\xc3\xa1vn\xc4\x9bn\xc3\xad</h\
2>\x0a<p><b>Z\xc3\xa1klad\
n\xc3\xad</b> \xc3\xbarove\xc5\x88\
 zobrazuje z\xc3\xa1kl\
adn\xc3\xad nastaven\xc3\xad\
; na z\xc3\xa1kladn\xc3\xad \
\xc3\xbarovni se \xc4\x8dty\xc5\
\x99i rampy\x0anastavu\
j\xc3\xad spole\xc4\x8dn\xc4\x9b. \
<b>Expertn\xc3\xad</b>\
 \xc3\xbarove\xc5\x88 p\xc5\x99id\xc3\
\xa1v\xc3\xa1 regul\xc3\xa1tory\
, linearizace a \
nastaven\xc3\xad\x0aexter\
n\xc3\xadho sn\xc3\xadma\xc4\x8de \
a je chr\xc3\xa1n\xc4\x9bna \
heslem. Heslo p\xc5\
\x99i dod\xc3\xa1n\xc3\xad je <\
code>expert</cod\
e>; na expertn\xc3\xad\
\x0a\xc3\xbarovni jej zm\xc4\
\x9bn\xc3\xadte v menu N\xc3\
\xa1hled \xe2\x86\x92 \xc3\x9arove\
\xc5\x88 opr\xc3\xa1vn\xc4\x9bn\xc3\xad \
\xe2\x86\x92 Zm\xc4\x9bnit hesl\
o pro expertn\xc3\xad \
\xc3\xbarove\xc5\x88.\x0aProgra\
m ukl\xc3\xa1d\xc3\xa1 pouze\
 jeho osolen\xc3\xbd h\
ash.</p>\x0a<p>\xc3\x9aro\
vn\xc4\x9b opr\xc3\xa1vn\xc4\x9bn\xc3\
\xad chr\xc3\xa1n\xc3\xad p\xc5\x99ed\
 ne\xc3\xbamysln\xc3\xbdmi z\
m\xc4\x9bnami, ne p\xc5\x99e\
d t\xc3\xadm, kdo m\xc5\xaf\xc5\
\xbee upravovat nas\
taven\xc3\xad\x0aprogramu\
: odstran\xc4\x9bn\xc3\xadm \
polo\xc5\xbeky <code>a\
ccess/expert_pas\
sword</code> z n\
astaven\xc3\xad plat\xc3\xad\
 op\xc4\x9bt heslo\x0ap\xc5\x99\
i dod\xc3\xa1n\xc3\xad. Soub\
or parametr\xc5\xaf ob\
sahuje v\xc5\xa1echny \
hodnoty bez ohle\
du na \xc3\xbarove\xc5\x88: \
pokud u\xc5\xbeivatel \
na\x0az\xc3\xa1kladn\xc3\xad \xc3\xba\
rovni odes\xc3\xadl\xc3\xa1 \
dokument, jeho\xc5\xbe\
 hodnoty expertn\
\xc3\xad \xc3\xbarovn\xc4\x9b se l\
i\xc5\xa1\xc3\xad od hodnot \
ventilu,\x0aprogram\
 se nejprve zept\
\xc3\xa1.</p>\x0a\x0a<h2>Onl\
ine a offline</h\
2>\x0a<p>Komunikace\
 \xe2\x86\x92 HID konfigu\
race zobraz\xc3\xad ve\
ntily p\xc5\x99ipojen\xc3\
\xa9 p\xc5\x99es USB a em\
ulovan\xc3\xa9 ventily\
;\x0aemulovan\xc3\xbd ven\
til p\xc5\x99id\xc3\xa1te za\
d\xc3\xa1n\xc3\xadm typov\xc3\xa9h\
o kl\xc3\xad\xc4\x8de a v\xc3\xbdr\
obn\xc3\xadho \xc4\x8d\xc3\xadsla.\
 Komunikace \xe2\x86\x92 \
Re\xc5\xbeim online\x0ana\
v\xc3\xa1\xc5\xbee spojen\xc3\xad.\
 Li\xc5\xa1\xc3\xad-li se ot\
ev\xc5\x99en\xc3\xbd z\xc3\xa1znam\
 parametr\xc5\xaf od v\
entilu, program \
zobraz\xc3\xad rozd\xc3\xadl\
y a\x0azept\xc3\xa1 se, z\
da p\xc5\x99evz\xc3\xadt hod\
noty ventilu, od\
eslat hodnoty do\
kumentu (na\xc4\x8dten\
\xc3\xad do ventilu) n\
ebo\x0azru\xc5\xa1it. V r\
e\xc5\xbeimu online jd\
e ka\xc5\xbed\xc3\xa1 zm\xc4\x9bna\
 ihned do ventil\
u i do dokumentu\
, v re\xc5\xbeimu offl\
ine\x0apouze do dok\
umentu. Ztrat\xc3\xad-\
li se spojen\xc3\xad s\
 ventilem, progr\
am p\xc5\x99ejde do re\
\xc5\xbeimu offline a\x0a\
v\xc5\xa1echny hodnoty\
 zachov\xc3\xa1.</p>\x0a<\
p>Hodnoty zm\xc4\x9bn\xc4\
\x9bn\xc3\xa9 online jsou\
 ve ventilu akti\
vn\xc3\xad, ale je\xc5\xa1t\xc4\
\x9b neulo\xc5\xbeen\xc3\xa9: p\
\xc5\x99i p\xc5\x99echodu do\
\x0are\xc5\xbeimu offline\
 program nab\xc3\xaddn\
e jejich ulo\xc5\xbeen\
\xc3\xad. <b>Na\xc4\x8dten\xc3\xad\
 do ventilu</b> \
zap\xc3\xad\xc5\xa1e v\xc5\xa1echn\
y\x0ahodnoty, p\xc5\x99e\xc4\
\x8dte je zp\xc4\x9bt, po\
rovn\xc3\xa1 a ulo\xc5\xbe\xc3\xad\
; ulo\xc5\xbe\xc3\xad se jen\
 tehdy, je-li ka\
\xc5\xbed\xc3\xa1 hodnota ov\
\xc4\x9b\xc5\x99ena.\x0aP\xc5\x99ed p\
rvn\xc3\xadm na\xc4\x8dten\xc3\xad\
m do ventilu pro\
gram ulo\xc5\xbe\xc3\xad z\xc3\xa1\
lohu vlastn\xc3\xadch \
parametr\xc5\xaf venti\
lu do slo\xc5\xbeky\x0au\xc5\
\xbeivatelsk\xc3\xbdch da\
t (<code>backups\
/&lt;v\xc3\xbdrobn\xc3\xad \xc4\
\x8d\xc3\xadslo&gt;/</cod\
e>).</p>\x0a<p><b>R\
estart ventilu</\
b> a <b>Obnoven\xc3\
\xad tov\xc3\xa1rn\xc3\xadho na\
staven\xc3\xad</b> jso\
u dovoleny pouze\
 p\xc5\x99i\x0aodpojen\xc3\xa9m\
 hydraulick\xc3\xa9m o\
bvodu; program v\
\xc3\xa1s po\xc5\xbe\xc3\xa1d\xc3\xa1 o \
potvrzen\xc3\xad.</p>\x0a\
\x0a<h2>Soubory</h2\
>\x0a<p>Z\xc3\xa1znamy pa\
rametr\xc5\xaf (<code>\
*.prm</code>) js\
ou textov\xc3\xa9 soub\
ory. Otev\xc5\x99\xc3\xadt, \
Ulo\xc5\xbeit, Ulo\xc5\xbeit\
 jako,\x0anaposledy\
 otev\xc5\x99en\xc3\xa9 soub\
ory a p\xc5\x99eta\xc5\xbeen\
\xc3\xad my\xc5\xa1\xc3\xad funguj\
\xc3\xad obvykl\xc3\xbdm zp\xc5\
\xafsobem; p\xc5\x99ed zt\
r\xc3\xa1tou\x0aneulo\xc5\xbeen\
\xc3\xbdch zm\xc4\x9bn se pr\
ogram zept\xc3\xa1. Ka\
\xc5\xbedou zm\xc4\x9bnu lze\
 vr\xc3\xa1tit (Ctrl+Z\
) a znovu prov\xc3\xa9\
st\x0a(Ctrl+Y). Sou\
bor \xe2\x86\x92 Tisk a S\
oubor \xe2\x86\x92 Export\
 do PDF vytvo\xc5\x99\xc3\
\xad protokol param\
etr\xc5\xaf s typov\xc3\xbdm\
 kl\xc3\xad\xc4\x8dem,\x0av\xc3\xbdro\
bn\xc3\xadm \xc4\x8d\xc3\xadslem, \
firmware, soubor\
em, datem, \xc3\xbarov\
n\xc3\xad opr\xc3\xa1vn\xc4\x9bn\xc3\xad\
, postupov\xc3\xbdm di\
agramem a v\xc5\xa1emi\
\x0aparametry s jed\
notkami.</p>\x0a\x0a<h\
2>Kl\xc3\xa1vesnice</h\
2>\x0a<table>\x0a<tr><\
td>Ctrl+O / Ctrl\
+S / Ctrl+Shift+\
S</td><td>Otev\xc5\x99\
\xc3\xadt / Ulo\xc5\xbeit / \
Ulo\xc5\xbeit jako</td\
></tr>\x0a<tr><td>C\
trl+Z / Ctrl+Y</\
td><td>Zp\xc4\x9bt / Z\
novu</td></tr>\x0a<\
tr><td>Ctrl+P / \
Ctrl+E</td><td>T\
isk / Export do \
PDF</td></tr>\x0a<t\
r><td>Ctrl+1 / C\
trl+2 / Ctrl+3 /\
 Ctrl+4</td><td>\
Postupov\xc3\xbd diagr\
am / Seznam para\
metr\xc5\xaf / Oscilos\
kop / Okno CANop\
en</td></tr>\x0a<tr\
><td>F5 / Shift+\
F5</td><td>Re\xc5\xbei\
m online / Re\xc5\xbei\
m offline</td></\
tr>\x0a<tr><td>Ctrl\
+U / Ctrl+D</td>\
<td>Na\xc4\x8dten\xc3\xad do\
 ventilu / Sta\xc5\xbe\
en\xc3\xad z ventilu</\
td></tr>\x0a<tr><td\
>Ctrl+T / Ctrl+I\
 / Ctrl+H</td><t\
d>V\xc3\xbdb\xc4\x9br ventil\
u / Stav ventilu\
 / HID konfigura\
ce</td></tr>\x0a</t\
able>\x0a</body>\x0a</\
html>\x0a\
\x00\x00\x13\xb1\
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
>\x0a\x0a<h2>Start</h2\
>\x0a<ul>\x0a<li><code\
>prm9tool</code>\
 \xc3\xb6ffnet das Fen\
ster mit einem n\
euen Parametersa\
tz.</li>\x0a<li><co\
de>prm9tool DATE\
I.prm</code> \xc3\xb6f\
fnet eine Parame\
terdatei.</li>\x0a<\
li><code>prm9too\
l --emulator [TY\
PSCHL\xc3\x9cSSEL[:SER\
IENNUMMER]]</cod\
e> startet onlin\
e mit einem\x0aemul\
ierten Ventil (S\
tandard-Typschl\xc3\
\xbcssel <code>PRM9\
-06.3Z11/30-24E0\
2S02-CA</code>).\
</li>\x0a</ul>\x0a\x0a<h2\
>Das Fenster</h2\
>\x0a<p>Hauptmen\xc3\xbc,\
 Werkzeugleiste,\
 Hauptfl\xc3\xa4che un\
d Statuszeile. D\
ie Statuszeile z\
eigt den\x0aKommuni\
kationsmodus, de\
n Zustand des Ve\
ntils (<i>ok</i>\
 oder den aktive\
n Fehler), die\x0aF\
irmware-Version,\
 den Typschl\xc3\xbcss\
el und den Datei\
namen; <b>*</b> \
kennzeichnet ung\
espeicherte\x0a\xc3\x84nd\
erungen.</p>\x0a<p>\
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
 verbindet. Weic\
ht der ge\xc3\xb6ffnet\
e Parametersatz \
vom Ventil ab,\x0az\
eigt das Program\
m die Unterschie\
de und fragt, ob\
 die Werte des V\
entils \xc3\xbcbernomm\
en, die\x0aWerte de\
s Dokuments gese\
ndet (Hochladen)\
 oder abgebroche\
n werden soll. O\
nline geht jede\x0a\
\xc3\x84nderung sofort\
 an das Ventil u\
nd in das Dokume\
nt, offline nur \
in das Dokument.\
 Geht die\x0aVerbin\
dung verloren, s\
chaltet das Prog\
ramm auf offline\
 und beh\xc3\xa4lt all\
e Werte.</p>\x0a<p>\
Online ge\xc3\xa4ndert\
e Werte sind im \
Ventil aktiv, ab\
er noch nicht ge\
speichert: beim \
Wechsel\x0aauf offl\
ine bietet das P\
rogramm an, sie \
zu speichern. <b\
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
\xa4tigen.</p>\x0a\x0a<h2\
>Dateien</h2>\x0a<p\
>Parameterdateie\
n (<code>*.prm</\
code>) sind Text\
dateien. \xc3\x96ffnen\
, Speichern, Spe\
ichern\x0aunter, di\
e zuletzt ge\xc3\xb6ff\
neten Dateien un\
d Drag &amp; Dro\
p funktionieren \
wie gewohnt; vor\
 dem\x0aVerlust ung\
espeicherter \xc3\x84n\
derungen fragt d\
as Programm nach\
. Jede \xc3\x84nderung\
 l\xc3\xa4sst sich\x0ar\xc3\xbc\
ckg\xc3\xa4ngig machen\
 (Strg+Z) und wi\
ederherstellen (\
Strg+Y). Datei \xe2\
\x86\x92 Drucken und D\
atei \xe2\x86\x92 PDF\x0aexp\
ortieren erzeuge\
n ein Parameterp\
rotokoll mit Typ\
schl\xc3\xbcssel, Seri\
ennummer, Firmwa\
re, Datei,\x0aDatum\
, Berechtigungss\
tufe, dem Ablauf\
diagramm und all\
en Parametern mi\
t Einheit.</p>\x0a\x0a\
<h2>Tastatur</h2\
>\x0a<table>\x0a<tr><t\
d>Strg+O / Strg+\
S / Strg+Umschal\
t+S</td><td>\xc3\x96ff\
nen / Speichern \
/ Speichern unte\
r</td></tr>\x0a<tr>\
<td>Strg+Z / Str\
g+Y</td><td>R\xc3\xbcc\
kg\xc3\xa4ngig / Wiede\
rherstellen</td>\
</tr>\x0a<tr><td>St\
rg+P / Strg+E</t\
d><td>Drucken / \
PDF exportieren<\
/td></tr>\x0a<tr><t\
d>Strg+1 / Strg+\
2 / Strg+3 / Str\
g+4</td><td>Abla\
ufdiagramm / Par\
ameterliste / Os\
zilloskop / CANo\
pen-Fenster</td>\
</tr>\x0a<tr><td>F5\
 / Umschalt+F5</\
td><td>Online / \
Offline</td></tr\
>\x0a<tr><td>Strg+U\
 / Strg+D</td><t\
d>In das Ventil \
hochladen / Aus \
dem Ventil herun\
terladen</td></t\
r>\x0a<tr><td>Strg+\
T / Strg+I / Str\
g+H</td><td>Vent\
ilauswahl / Vent\
ilstatus / HID-K\
onfiguration</td\
></tr>\x0a</table>\x0a\
</body>\x0a</html>\x0a\
\
\x00\x00\x10\xfd\
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
/p>\x0a\x0a<h2>Startin\
g</h2>\x0a<ul>\x0a<li>\
<code>prm9tool</\
code> opens the \
window with a ne\
w parameter set.\
</li>\x0a<li><code>\
prm9tool FILE.pr\
m</code> opens a\
 parameter file.\
</li>\x0a<li><code>\
prm9tool --emula\
tor [TYPEKEY[:SE\
RIAL]]</code> st\
arts online with\
 an emulated val\
ve\x0a(default type\
 key <code>PRM9-\
06.3Z11/30-24E02\
S02-CA</code>).<\
/li>\x0a</ul>\x0a\x0a<h2>\
The window</h2>\x0a\
<p>Main menu, to\
olbar, main area\
 and status bar.\
 The status bar \
shows the commun\
ication mode,\x0ath\
e valve state (<\
i>ok</i> or the \
active error), t\
he firmware vers\
ion, the type ke\
y and the\x0afile n\
ame; <b>*</b> ma\
rks unsaved chan\
ges.</p>\x0a<p>The \
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
e connects. If t\
he open paramete\
r set differs fr\
om the valve's, \
the program list\
s the\x0adifference\
s and asks wheth\
er to take the v\
alve's values, s\
end the document\
's values\x0a(uploa\
d) or cancel. On\
line, every chan\
ge goes to the v\
alve at once and\
 into the docume\
nt;\x0aoffline, int\
o the document o\
nly. If the valv\
e is lost, the p\
rogram goes offl\
ine and keeps\x0aev\
ery value.</p>\x0a<\
p>Values changed\
 online are acti\
ve in the valve \
but not yet stor\
ed: going offlin\
e offers to\x0astor\
e them. <b>Uploa\
d to valve</b> w\
rites all values\
, reads them bac\
k, compares and \
stores\x0athem; not\
hing is stored u\
nless every valu\
e was verified. \
Before the first\
 upload to a val\
ve\x0athe program s\
aves a backup of\
 the valve's own\
 parameters in t\
he user data fol\
der\x0a(<code>backu\
ps/&lt;serial&gt\
;/</code>).</p>\x0a\
<p><b>Restart va\
lve</b> and <b>R\
estore factory v\
alues</b> are al\
lowed only with \
the\x0ahydraulics d\
isconnected; the\
 program asks yo\
u to confirm thi\
s.</p>\x0a\x0a<h2>File\
s</h2>\x0a<p>Parame\
ter files (<code\
>*.prm</code>) a\
re text files. O\
pen, Save, Save \
As, the recent\x0af\
iles and drag an\
d drop work as u\
sual; the progra\
m asks before un\
saved changes ar\
e lost.\x0aEvery ch\
ange can be undo\
ne (Ctrl+Z) and \
redone (Ctrl+Y).\
 File \xe2\x86\x92 Print \
and File \xe2\x86\x92 Exp\
ort PDF\x0aproduce \
a parameter reco\
rd with type key\
, serial number,\
 firmware, file,\
 date, access le\
vel,\x0athe flow di\
agram and every \
parameter with i\
ts unit.</p>\x0a\x0a<h\
2>Keyboard</h2>\x0a\
<table>\x0a<tr><td>\
Ctrl+O / Ctrl+S \
/ Ctrl+Shift+S</\
td><td>Open / Sa\
ve / Save As</td\
></tr>\x0a<tr><td>C\
trl+Z / Ctrl+Y</\
td><td>Undo / Re\
do</td></tr>\x0a<tr\
><td>Ctrl+P / Ct\
rl+E</td><td>Pri\
nt / Export PDF<\
/td></tr>\x0a<tr><t\
d>Ctrl+1 / Ctrl+\
2 / Ctrl+3 / Ctr\
l+4</td><td>Flow\
 diagram / Param\
eter list / Osci\
lloscope / CANop\
en window</td></\
tr>\x0a<tr><td>F5 /\
 Shift+F5</td><t\
d>Online / Offli\
ne</td></tr>\x0a<tr\
><td>Ctrl+U / Ct\
rl+D</td><td>Upl\
oad to valve / D\
ownload from val\
ve</td></tr>\x0a<tr\
><td>Ctrl+T / Ct\
rl+I / Ctrl+H</t\
d><td>Valve sele\
ction / Valve st\
atus / HID confi\
guration</td></t\
r>\x0a</table>\x0a</bo\
dy>\x0a</html>\x0a\
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
\x00\x0c\
\x07\xbc\x97\x9c\
\x00h\
\x00e\x00l\x00p\x00_\x00c\x00s\x00.\x00h\x00t\x00m\x00l\
\x00\x0c\
\x07\xdc\x97\x9c\
\x00h\
\x00e\x00l\x00p\x00_\x00d\x00e\x00.\x00h\x00t\x00m\x00l\
\x00\x0c\
\x09\xcc\x97\x9c\
\x00h\
\x00e\x00l\x00p\x00_\x00e\x00n\x00.\x00h\x00t\x00m\x00l\
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
\x00\x00\x00\x10\x00\x02\x00\x00\x00\x03\x00\x00\x00\x10\
\x00\x00\x00\x00\x00\x02\x00\x00\x00\x0d\x00\x00\x00\x03\
\x00\x00\x00\xfc\x00\x00\x00\x00\x00\x01\x00\x00?U\
\x00\x00\x00\x92\x00\x00\x00\x00\x00\x01\x00\x009\xb7\
\x00\x00\x01\x9e\x00\x00\x00\x00\x00\x01\x00\x00I\x8b\
\x00\x00\x01\x16\x00\x00\x00\x00\x00\x01\x00\x00@\x82\
\x00\x00\x00x\x00\x00\x00\x00\x00\x01\x00\x007\xf1\
\x00\x00\x01\xba\x00\x00\x00\x00\x00\x01\x00\x00K#\
\x00\x00\x01.\x00\x00\x00\x00\x00\x01\x00\x00BQ\
\x00\x00\x01\x80\x00\x00\x00\x00\x00\x01\x00\x00G\xdf\
\x00\x00\x00\xaa\x00\x00\x00\x00\x00\x01\x00\x00;]\
\x00\x00\x01J\x00\x00\x00\x00\x00\x01\x00\x00D\x1a\
\x00\x00\x00\xc6\x00\x00\x00\x00\x00\x01\x00\x00<Z\
\x00\x00\x00\xe2\x00\x00\x00\x00\x00\x01\x00\x00>\x13\
\x00\x00\x01^\x00\x00\x00\x00\x00\x01\x00\x00F\x9e\
\x00\x00\x00\x1e\x00\x00\x00\x00\x00\x01\x00\x00\x00\x00\
\x00\x00\x00<\x00\x00\x00\x00\x00\x01\x00\x00\x13;\
\x00\x00\x00Z\x00\x00\x00\x00\x00\x01\x00\x00&\xf0\
"

def qInitResources():
    QtCore.qRegisterResourceData(0x01, qt_resource_struct, qt_resource_name, qt_resource_data)

def qCleanupResources():
    QtCore.qUnregisterResourceData(0x01, qt_resource_struct, qt_resource_name, qt_resource_data)

qInitResources()
