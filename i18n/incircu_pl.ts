<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pl_PL">
<context>
    <name>IncirCuAlgorithm</name>
    <message>
        <location filename="../algorithms/base.py" line="80"/>
        <source>Centerlines</source>
        <translation>Linie środkowe</translation>
    </message>
    <message>
        <location filename="../algorithms/dependencies.py" line="159"/>
        <source>IncirCu needs the Python package Shapely 2, which is not installed.</source>
        <translation>IncirCu wymaga pakietu Pythona Shapely 2, który nie jest zainstalowany.</translation>
    </message>
    <message>
        <location filename="../algorithms/dependencies.py" line="167"/>
        <source>IncirCu needs Shapely 2.0 or newer, but Shapely {} is installed.</source>
        <translation>IncirCu wymaga Shapely 2.0 lub nowszego, a zainstalowany jest Shapely {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/options.py" line="172"/>
        <source>{} must be a {} layer, but &apos;{}&apos; holds {} geometries.</source>
        <translation>{} musi być warstwą typu {}, a '{}' zawiera geometrie typu {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="69"/>
        <source>the feature has no geometry</source>
        <translation>obiekt nie ma geometrii</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="147"/>
        <source>Feature {} skipped: {}</source>
        <translation>Obiekt {} pominięty: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="155"/>
        <source>Feature {}: {}</source>
        <translation>Obiekt {}: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="176"/>
        <source>{} (part {})</source>
        <translation>{} (część {})</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="214"/>
        <source>unexpected {}: {} (please report this with the feature)</source>
        <translation>nieoczekiwany błąd {}: {} (prosimy zgłosić go wraz z obiektem)</translation>
    </message>
    <message>
        <location filename="../algorithms/outputs.py" line="250"/>
        <source>Could not write a centerline: {}</source>
        <translation>Nie udało się zapisać linii środkowej: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/options.py" line="213"/>
        <source>Give either a largest deviation from the axis (adaptive sampling) or a fixed boundary sampling distance, not both; set the other one to 0.</source>
        <translation>Podaj największe odchylenie od osi (próbkowanie adaptacyjne) albo stały odstęp próbkowania brzegu, nie oba; ustaw drugie na 0.</translation>
    </message>
    <message>
        <location filename="../algorithms/network_outputs.py" line="161"/>
        <source>Could not write a branch: {}</source>
        <translation>Nie można zapisać gałęzi: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/units.py" line="23"/>
        <source>layer units</source>
        <translation>jednostki warstwy</translation>
    </message>
    <message>
        <location filename="../algorithms/options.py" line="234"/>
        <source>{}: {} has no field &apos;{}&apos;; its fields are: {}.</source>
        <translation>{}: {} nie ma pola '{}'; jego pola to: {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/options.py" line="234"/>
        <source>none</source>
        <translation>brak</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="106"/>
        <source>Z values are ignored: &apos;{}&apos; has Z, but the centerline is computed in the plane and written without Z (its M values, when stored, are the local width).</source>
        <translation>Wartości Z są pomijane: '{}' ma współrzędną Z, ale linia środkowa jest obliczana na płaszczyźnie i zapisywana bez Z (jej wartości M, jeśli są zapisywane, to lokalna szerokość).</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="110"/>
        <source>centerlines</source>
        <translation>linie środkowe</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="111"/>
        <source>vertices</source>
        <translation>wierzchołki</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="112"/>
        <source>transects</source>
        <translation>przekroje</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="113"/>
        <source>incircles</source>
        <translation>okręgi wpisane</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="126"/>
        <source>{layer} — {output} ({rule})</source>
        <translation>{layer} — {output} ({rule})</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="126"/>
        <source>{layer} — {output}</source>
        <translation>{layer} — {output}</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="42"/>
        <source>metres</source>
        <translation>metry</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="43"/>
        <source>kilometres</source>
        <translation>kilometry</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="44"/>
        <source>feet</source>
        <translation>stopy</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="45"/>
        <source>yards</source>
        <translation>jardy</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="46"/>
        <source>miles</source>
        <translation>mile</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="47"/>
        <source>nautical miles</source>
        <translation>mile morskie</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="48"/>
        <source>centimetres</source>
        <translation>centymetry</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="49"/>
        <source>millimetres</source>
        <translation>milimetry</translation>
    </message>
    <message>
        <location filename="../algorithms/label_outputs.py" line="81"/>
        <source>Could not write a label: {}</source>
        <translation>Nie można zapisać etykiety: {}</translation>
    </message>
</context>
<context>
    <name>IncirCuCore</name>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="30"/>
        <source>polygon</source>
        <translation>poligon</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="31"/>
        <source>exterior ring</source>
        <translation>pierścień zewnętrzny</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="32"/>
        <source>pair of lines</source>
        <translation>para linii</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="33"/>
        <source>first line</source>
        <translation>pierwsza linia</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="34"/>
        <source>second line</source>
        <translation>druga linia</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="35"/>
        <source>first chain</source>
        <translation>pierwszy łańcuch</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="36"/>
        <source>second chain</source>
        <translation>drugi łańcuch</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="43"/>
        <source>split points</source>
        <translation>punkty podziału</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="38"/>
        <source>line</source>
        <translation>linia</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="39"/>
        <source>chain</source>
        <translation>łańcuch</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="40"/>
        <source>The polygon</source>
        <translation>Poligon</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="41"/>
        <source>The part</source>
        <translation>Część</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="42"/>
        <source>split point</source>
        <translation>punkt podziału</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="49"/>
        <source>a network needs at least 2</source>
        <translation>sieć potrzebuje co najmniej 2</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="51"/>
        <source>Unknown island mode {mode!r}; use one of {choices}.</source>
        <translation>Nieznany tryb wysp {mode!r}; użyj jednego z: {choices}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="52"/>
        <source>Unknown end rule {rule!r}; use one of {choices}.</source>
        <translation>Nieznana reguła końców {rule!r}; użyj jednej z: {choices}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="53"/>
        <source>{name} must be a number (a length in {units}), got {value!r}.</source>
        <translation>{name} musi być liczbą (długością w: {units}), podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="56"/>
        <source>{name} must be a positive, finite length in {units} (or 0 for automatic), got {value!r}.</source>
        <translation>{name} musi być dodatnią, skończoną długością w: {units} (lub 0 = automatycznie), podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="59"/>
        <source>{name} must be a non-negative, finite distance in {units} (or None), got {value!r}.</source>
        <translation>{name} musi być nieujemną, skończoną odległością w: {units} (lub None), podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="62"/>
        <source>{name} must be a number, got {kind} {value!r}.</source>
        <translation>{name} musi być liczbą, podano {kind} {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="77"/>
        <source>samples_per_chain must be a whole number, got {value!r}.</source>
        <translation>samples_per_chain musi być liczbą całkowitą, podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="78"/>
        <source>The number of samples per chain must be at least 1, got {value!r}.</source>
        <translation>Liczba próbek na łańcuch musi wynosić co najmniej 1, podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="88"/>
        <source>Give either a tolerance (adaptive sampling) or a spacing / sample count (fixed sampling).</source>
        <translation>Podaj tolerancję (próbkowanie adaptacyjne) albo odstęp lub liczbę próbek (próbkowanie stałe), nie oba.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="109"/>
        <source>A circle needs at least 1 segment per quarter, got {value!r}.</source>
        <translation>Okrąg potrzebuje co najmniej 1 odcinka na ćwiartkę, podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="112"/>
        <source>The transect interval must be a distance, got {value!r}.</source>
        <translation>Odstęp przekrojów musi być odległością, podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="115"/>
        <source>The transect interval must be a positive distance, got {value!r}.</source>
        <translation>Odstęp przekrojów musi być dodatnią odległością, podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="118"/>
        <source>{guides} guides were given for {polygons} polygons.</source>
        <translation>Podano linii prowadzących: {guides}, a poligonów: {polygons}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="130"/>
        <source>The polygon is null (no geometry).</source>
        <translation>Poligon jest pusty (brak geometrii).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="131"/>
        <source>The polygon is empty.</source>
        <translation>Poligon jest pusty.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="132"/>
        <source>Expected a polygon or multipolygon, got a {kind}.</source>
        <translation>Oczekiwano poligonu lub multipoligonu, podano {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="133"/>
        <source>Expected a single polygon, got a {kind}.</source>
        <translation>Oczekiwano pojedynczego poligonu, podano {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="134"/>
        <source>The polygon is not valid: {reason}. Repair it first (e.g. QGIS &apos;{fix_geometries}&apos;).</source>
        <translation>Poligon jest nieprawidłowy: {reason}. Najpierw go napraw (np. narzędziem QGIS „{fix_geometries}”).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="137"/>
        <source>The {name} is null (no geometry).</source>
        <translation>Obiekt „{name}” nie ma geometrii.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="138"/>
        <source>The {name} is empty.</source>
        <translation>Obiekt „{name}” jest pusty.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="139"/>
        <source>The {name} must be a single line, not a {kind}.</source>
        <translation>Obiekt „{name}” musi być pojedynczą linią, a nie {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="140"/>
        <source>The {name} must be an (n, 2) array of numbers.</source>
        <translation>Obiekt „{name}” musi być tablicą liczb (n, 2).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="141"/>
        <source>The {name} must be an (n, 2) coordinate array.</source>
        <translation>Obiekt „{name}” musi być tablicą współrzędnych (n, 2).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="142"/>
        <source>The {name} has a NaN or infinite coordinate: {value}.</source>
        <translation>Obiekt „{name}” ma współrzędną NaN lub nieskończoną: {value}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="159"/>
        <source>The polygon&apos;s size ({size:.3g}) is absurd for its coordinates&apos; units; reproject or rescale it.</source>
        <translation>Rozmiar poligonu ({size:.3g}) jest niedorzeczny dla jednostek jego współrzędnych; przelicz go do innego układu lub przeskaluj.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="162"/>
        <source>The boundary has {count:,} segments, more than this engine can index.</source>
        <translation>Obrys ma {count:,} odcinków, więcej niż ten silnik może zindeksować.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="165"/>
        <source>A guide must be a line or multiline, got a {kind}.</source>
        <translation>Linia prowadząca musi być linią lub multilinią, podano {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="166"/>
        <source>The guide line has a NaN or infinite coordinate.</source>
        <translation>Linia prowadząca ma współrzędną NaN lub nieskończoną.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="167"/>
        <source>Island {index} is empty or has a NaN or infinite coordinate.</source>
        <translation>Wyspa {index} jest pusta lub ma współrzędną NaN lub nieskończoną.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="170"/>
        <source>Island {index} has fewer than 3 distinct points.</source>
        <translation>Wyspa {index} ma mniej niż 3 różne punkty.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="171"/>
        <source>Cannot centre a projection on a null geometry.</source>
        <translation>Nie można wyśrodkować odwzorowania na braku geometrii.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="172"/>
        <source>Cannot centre a projection on an empty geometry.</source>
        <translation>Nie można wyśrodkować odwzorowania na pustej geometrii.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="173"/>
        <source>Cannot centre a projection on a geometry with a NaN or infinite coordinate.</source>
        <translation>Nie można wyśrodkować odwzorowania na geometrii ze współrzędną NaN lub nieskończoną.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="184"/>
        <source>Unknown CRS {crs!r}: {error}</source>
        <translation>Nieznany układ współrzędnych {crs!r}: {error}</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="185"/>
        <source>{name} is not a geographic CRS.</source>
        <translation>{name} nie jest układem geograficznym.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="187"/>
        <source>The {name} has fewer than 2 distinct points.</source>
        <translation>Obiekt „{name}” ma mniej niż 2 różne punkty.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="188"/>
        <source>The {name} folds back over itself at {point}.</source>
        <translation>Obiekt „{name}” zawraca na sobie w punkcie {point}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="189"/>
        <source>The {name} crosses itself at {point}.</source>
        <translation>Obiekt „{name}” przecina sam siebie w punkcie {point}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="190"/>
        <source>The two lines cross or touch at {point}; they must bound a region between them.</source>
        <translation>Obie linie przecinają się lub stykają w punkcie {point}; muszą ograniczać obszar między sobą.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="198"/>
        <source>The two lines enclose no area between them (they lie on one line).</source>
        <translation>Obie linie nie ograniczają żadnego obszaru (leżą na jednej prostej).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="201"/>
        <source>The chains are too close together or too short to carry a centerline.</source>
        <translation>Łańcuchy są zbyt blisko siebie lub zbyt krótkie, by wyznaczyć linię środkową.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="245"/>
        <source>A polygon needs exactly 2 split points on its boundary, got {count}.</source>
        <translation>Poligon potrzebuje dokładnie 2 punktów podziału na obrysie, podano: {count}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="248"/>
        <source>Both split points snap to the same place {point} of the boundary.</source>
        <translation>Oba punkty podziału przyciągają się do tego samego miejsca {point} obrysu.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="251"/>
        <source>Split points must be a sequence of two points (or a MultiPoint), got a {kind}.</source>
        <translation>Punkty podziału muszą być ciągiem dwóch punktów (lub multipunktem), podano {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="254"/>
        <source>Split point {index} is an empty point.</source>
        <translation>Punkt podziału {index} jest pusty.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="255"/>
        <source>Split point {index} must be a point, not a {kind}.</source>
        <translation>Punkt podziału {index} musi być punktem, a nie {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="260"/>
        <source>Split point {index} must be an (x, y) pair of numbers, got {value!r}.</source>
        <translation>Punkt podziału {index} musi być parą liczb (x, y), podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="263"/>
        <source>A split point has a NaN or infinite coordinate.</source>
        <translation>Punkt podziału ma współrzędną NaN lub nieskończoną.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="268"/>
        <source>The ends of the polygon cannot be found: {error}.</source>
        <translation>Nie można wyznaczyć końców poligonu: {error}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="290"/>
        <source>The polygon&apos;s outline could not be triangulated to find its ends automatically.</source>
        <translation>Nie udało się striangulować obrysu poligonu, by automatycznie wyznaczyć jego końce.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="293"/>
        <source>The guide line does not come near the polygon; its ends were found automatically.</source>
        <translation>Linia prowadząca nie przebiega w pobliżu poligonu; jego końce wyznaczono automatycznie.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="296"/>
        <source>The shape is not elongated; its automatically found ends are arbitrary.</source>
        <translation>Kształt nie jest wydłużony; jego automatycznie wyznaczone końce są przypadkowe.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="327"/>
        <source>The computed centerline has a NaN or infinite coordinate; none is returned.</source>
        <translation>Obliczona linia środkowa ma współrzędną NaN lub nieskończoną; nie zwrócono jej.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="348"/>
        <source>A network needs at least 2 split points on the boundary, got {count}.</source>
        <translation>Sieć potrzebuje co najmniej 2 punktów podziału na obrysie, podano: {count}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="351"/>
        <source>Two split points snap to the same place {point} of the boundary.</source>
        <translation>Dwa punkty podziału przyciągają się do tego samego miejsca {point} obrysu.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="354"/>
        <source>The split points could not be placed in order on the boundary with its islands.</source>
        <translation>Nie udało się uporządkować punktów podziału na obrysie z jego wyspami.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="367"/>
        <source>A branch of the network has fewer than 2 vertices; try a smaller spacing.</source>
        <translation>Gałąź sieci ma mniej niż 2 wierzchołki; spróbuj mniejszego odstępu.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="81"/>
        <source>A spacing of {spacing:.6g} would need about {planned:.3g} samples (at most {limit:.3g}); use a larger spacing.</source>
        <translation>Odstęp {spacing:.6g} wymagałby około {planned:.3g} próbek (najwyżej {limit:.3g}); użyj większego odstępu.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="143"/>
        <source>The {name} has a coordinate of magnitude {magnitude:.3g}, beyond {limit:.0e}: products of such coordinates overflow float64. Use a projected CRS in metres, or scale the data down.</source>
        <translation>Obiekt „{name}” ma współrzędną rzędu {magnitude:.3g}, powyżej {limit:.0e}: iloczyny takich współrzędnych przekraczają zakres float64. Użyj odwzorowanego układu w metrach albo zmniejsz skalę danych.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="148"/>
        <source>The {name} is {extent:.3g} across, under {limit:.0e}: products of its lengths underflow float64. Scale the data up (use smaller units).</source>
        <translation>Obiekt „{name}” ma rozmiar {extent:.3g}, poniżej {limit:.0e}: iloczyny jego długości wychodzą poza zakres float64. Powiększ skalę danych (użyj mniejszych jednostek).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="153"/>
        <source>The {name} is {extent:.3g} across at coordinates of magnitude {magnitude:.3g}: float64 cannot resolve a shape smaller than {limit:.0e} of its distance from the origin. Shift the data nearer the origin (subtract an offset) or use a local projected CRS.</source>
        <translation>Obiekt „{name}” ma rozmiar {extent:.3g} przy współrzędnych rzędu {magnitude:.3g}: float64 nie rozróżni kształtu mniejszego niż {limit:.0e} jego odległości od początku układu. Przesuń dane bliżej początku układu (odejmij przesunięcie) albo użyj lokalnego układu odwzorowanego.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="176"/>
        <source>The projection centre ({longitude!r}, {latitude!r}) is not a longitude and a latitude in degrees.</source>
        <translation>Środek odwzorowania ({longitude!r}, {latitude!r}) nie jest długością i szerokością geograficzną w stopniach.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="180"/>
        <source>A point could not be projected (a NaN or infinite coordinate, or a latitude beyond 90 degrees).</source>
        <translation>Nie udało się przeliczyć punktu (współrzędna NaN lub nieskończona albo szerokość geograficzna ponad 90 stopni).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="204"/>
        <source>The first line is {length:.6g} long, {ratio:.3g} times the second one ({other:.6g} {units}): it runs on beyond the other, where the region between them is closed by the straight gap between their ends, and the centerline follows that gap there. Cut the lines to where they face each other.</source>
        <translation>Pierwsza linia ma długość {length:.6g}, {ratio:.3g} razy więcej niż druga ({other:.6g} {units}): biegnie dalej niż druga, tam obszar między nimi zamyka prosty odcinek między ich końcami, a linia środkowa biegnie wzdłuż niego. Przytnij linie do odcinków leżących naprzeciw siebie.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="210"/>
        <source>The second line is {length:.6g} long, {ratio:.3g} times the first one ({other:.6g} {units}): it runs on beyond the other, where the region between them is closed by the straight gap between their ends, and the centerline follows that gap there. Cut the lines to where they face each other.</source>
        <translation>Druga linia ma długość {length:.6g}, {ratio:.3g} razy więcej niż pierwsza ({other:.6g} {units}): biegnie dalej niż pierwsza, tam obszar między nimi zamyka prosty odcinek między ich końcami, a linia środkowa biegnie wzdłuż niego. Przytnij linie do odcinków leżących naprzeciw siebie.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="235"/>
        <source>Split point {point} is {distance:.6g} {units} away from the polygon&apos;s boundary; the snap tolerance is {tolerance:.6g} {units}. Move the point onto the boundary or raise the tolerance.</source>
        <translation>Punkt podziału {point} leży {distance:.6g} {units} od obrysu poligonu; tolerancja przyciągania wynosi {tolerance:.6g} {units}. Przesuń punkt na obrys albo zwiększ tolerancję.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="240"/>
        <source>{subject} has {count} {points} within the snap tolerance ({tolerance:.6g} {units}) of its exterior ring; {needed}.</source>
        <translation>{subject}: liczba punktów podziału w granicach tolerancji przyciągania ({tolerance:.6g} {units}) od pierścienia zewnętrznego wynosi {count}; {needed}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="256"/>
        <source>Split point {index} is the number {value!r}: give a sequence of points, such as [(x1, y1), (x2, y2)].</source>
        <translation>Punkt podziału {index} jest liczbą {value!r}: podaj ciąg punktów, np. [(x1, y1), (x2, y2)].</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="264"/>
        <source>The ends found automatically coincide at {point}: the shape has no clear ends. Give two split points.</source>
        <translation>Automatycznie wyznaczone końce pokrywają się w punkcie {point}: kształt nie ma wyraźnych końców. Podaj dwa punkty podziału.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="321"/>
        <source>The island at {point} cannot be joined to a bank without crossing another island; use the option to ignore islands.</source>
        <translation>Wyspy w punkcie {point} nie da się połączyć z brzegiem bez przecięcia innej wyspy; użyj opcji pomijania wysp.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="330"/>
        <source>The computed centerline crosses itself, so none is returned. This happens where the shape has no single axis near the ends (a compact shape, or a split point in a corner): move the split points to the middle of the ends, or change the spacing.</source>
        <translation>Obliczona linia środkowa przecina samą siebie, więc jej nie zwrócono. Dzieje się tak, gdy kształt nie ma jednej osi przy końcach (zwarty kształt lub punkt podziału w narożniku): przesuń punkty podziału na środek końców albo zmień odstęp.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="336"/>
        <source>The computed centerline crosses itself at {point}, so none is returned. This happens where the shape has no single axis near the ends (a compact shape, or a split point in a corner): move the split points to the middle of the ends, or change the spacing.</source>
        <translation>Obliczona linia środkowa przecina samą siebie w punkcie {point}, więc jej nie zwrócono. Dzieje się tak, gdy kształt nie ma jednej osi przy końcach (zwarty kształt lub punkt podziału w narożniku): przesuń punkty podziału na środek końców albo zmień odstęp.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="342"/>
        <source>The computed centerline leaves the polygon at {point} ({outside:.6g} outside), so none is returned. Give split points, or change the tolerance.</source>
        <translation>Obliczona linia środkowa wychodzi poza poligon w punkcie {point} (o {outside:.6g}), więc jej nie zwrócono. Podaj punkty podziału albo zmień tolerancję.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="357"/>
        <source>The junction near {point} could not be located: its circle holds another chain out of order. Move the split points farther out along the arms.</source>
        <translation>Nie udało się wyznaczyć węzła w pobliżu punktu {point}: jego okrąg obejmuje inny łańcuch poza kolejnością. Przesuń punkty podziału dalej wzdłuż ramion.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="362"/>
        <source>The junction near {point} could not be located: its circle touches a chain at several places or a split point itself. Move the split points farther out along the arms.</source>
        <translation>Nie udało się wyznaczyć węzła w pobliżu punktu {point}: jego okrąg dotyka łańcucha w kilku miejscach lub samego punktu podziału. Przesuń punkty podziału dalej wzdłuż ramion.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="370"/>
        <source>The network found is not a tree with one end at each of the {k} split points ({branches} branches, {ends} ends, {weak} junctions of degree below 3); a split point may lie on a junction&apos;s circle: move the split points farther out along the arms.</source>
        <translation>Wyznaczona sieć nie jest drzewem z jednym końcem w każdym z {k} punktów podziału (gałęzie: {branches}, końce: {ends}, węzły stopnia mniejszego niż 3: {weak}); punkt podziału może leżeć na okręgu węzła: przesuń punkty podziału dalej wzdłuż ramion.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="91"/>
        <source>The tolerance {tolerance:.6g} ({units}) you set is below {relative:g} of the shape&apos;s extent ({extent:.6g} {units}): float64 cannot place vertices that finely. Use at least {least:.3g} ({units}), or 0 for the automatic tolerance.</source>
        <translation>Ustawiona tolerancja {tolerance:.6g} ({units}) jest mniejsza niż {relative:g} rozmiaru kształtu ({extent:.6g} {units}): float64 nie umieści wierzchołków tak dokładnie. Użyj co najmniej {least:.3g} ({units}) albo 0, by tolerancję dobrać automatycznie.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="97"/>
        <source>The shape is {width:.3g} {units} wide, {relative:.3g} of its extent ({extent:.6g} {units}): its automatic tolerance (the width / 200) is finer than float64 can place vertices, so the finest possible, {finest:.3g} {units} ({minimum:g} of the extent), is used.</source>
        <translation>Kształt ma szerokość {width:.3g} {units}, {relative:.3g} swojego rozmiaru ({extent:.6g} {units}): jego automatyczna tolerancja (szerokość / 200) jest drobniejsza, niż float64 potrafi rozmieścić wierzchołki, więc użyto najmniejszej możliwej, {finest:.3g} {units} ({minimum:g} rozmiaru).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="103"/>
        <source>The shape is {width:.3g} {units} wide (its area over its length), {relative:.3g} of its extent ({extent:.6g} {units}), under the {minimum:g} at which float64 can still tell its two sides apart: no centerline can be traced. At this width its sides are the centerline: use one of them.</source>
        <translation>Kształt ma szerokość {width:.3g} {units} (pole przez długość), {relative:.3g} swojego rozmiaru ({extent:.6g} {units}), poniżej {minimum:g}, przy których float64 jeszcze odróżnia jego dwa boki: nie da się wyznaczyć linii środkowej. Przy tej szerokości jego boki są linią środkową: użyj jednego z nich.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="119"/>
        <source>Unknown end cap {cap!r}; use one of {choices}.</source>
        <translation>Nieznany rodzaj końców linii {cap!r}; użyj jednego z: {choices}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="120"/>
        <source>Unknown transect style {style!r}; use one of {choices}.</source>
        <translation>Nieznany kształt przekroju poprzecznego {style!r}; użyj jednego z: {choices}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="123"/>
        <source>min_arm_ratio must be a finite number &gt;= 0, got {value!r}.</source>
        <translation>min_arm_ratio musi być skończoną liczbą &gt;= 0, podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="126"/>
        <source>min_arm_length must be a finite length &gt;= 0 ({units}), got {value!r}.</source>
        <translation>min_arm_length musi być skończoną długością &gt;= 0 ({units}), podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="193"/>
        <source>The two chains cross or touch at {point}; they must bound a region between them, meeting at most at shared end points.</source>
        <translation>Oba łańcuchy przecinają się lub stykają w punkcie {point}; muszą ograniczać obszar między sobą, spotykając się co najwyżej we wspólnych punktach końcowych.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="217"/>
        <source>A zero-width spike was removed from {places} before the centerline was computed.</source>
        <translation>Przed obliczeniem linii środkowej usunięto kolec o zerowej szerokości: {places}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="220"/>
        <source>{count} zero-width spikes were removed from {places} before the centerline was computed.</source>
        <translation>Przed obliczeniem linii środkowej usunięto kolce o zerowej szerokości (liczba: {count}): {places}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="223"/>
        <source>the exterior ring at {point} ({length:.6g} {units} long)</source>
        <translation>pierścień zewnętrzny w punkcie {point} (długość {length:.6g} {units})</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="226"/>
        <source>island {number} at {point} ({length:.6g} {units} long)</source>
        <translation>wyspa {number} w punkcie {point} (długość {length:.6g} {units})</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="227"/>
        <source>the first line at {point} ({length:.6g} {units} long)</source>
        <translation>pierwsza linia w punkcie {point} (długość {length:.6g} {units})</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="228"/>
        <source>the second line at {point} ({length:.6g} {units} long)</source>
        <translation>druga linia w punkcie {point} (długość {length:.6g} {units})</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="231"/>
        <source>{first}; {second}</source>
        <translation>{first}; {second}</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="232"/>
        <source>{first}; {second}; {third}</source>
        <translation>{first}; {second}; {third}</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="233"/>
        <source>{first}; {second}; {third}; and {more} more</source>
        <translation>{first}; {second}; {third} i jeszcze {more}</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="269"/>
        <source>The polygon is too thin or too small to find its ends automatically; give two split points.</source>
        <translation>Poligon jest zbyt cienki lub zbyt mały, by automatycznie wyznaczyć jego końce; podaj dwa punkty podziału.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="272"/>
        <source>The polygon is {width:.3g} {units} wide (its area over half its perimeter), {relative:.3g} of its extent ({extent:.6g} {units}), under the {minimum:g} at which its ends can be found automatically in float64; give two split points.</source>
        <translation>Poligon ma szerokość {width:.3g} {units} (pole przez połowę obwodu), {relative:.3g} swojego rozmiaru ({extent:.6g} {units}), poniżej {minimum:g}, przy których jego końce można w float64 wyznaczyć automatycznie; podaj dwa punkty podziału.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="278"/>
        <source>The polygon is too thin or too small to find its arms automatically.</source>
        <translation>Poligon jest zbyt cienki lub zbyt mały, by automatycznie wyznaczyć jego ramiona.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="281"/>
        <source>Only {count} arm end was found automatically on this polygon; give its ends as split points.</source>
        <translation>Na tym poligonie automatycznie znaleziono tylko tyle końców ramion: {count}; podaj jego końce jako punkty podziału.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="299"/>
        <source>The shape is star-like, with no dominant trunk; its automatic ends are the tips of its two farthest-apart arms.</source>
        <translation>Kształt jest gwiaździsty, bez dominującego głównego nurtu; jego automatyczne końce to końcówki dwóch najbardziej od siebie oddalonych ramion.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="304"/>
        <source>The shape is not elongated, with no dominant trunk; its automatic ends lie across its centre, along its longest axis.</source>
        <translation>Kształt nie jest wydłużony i nie ma dominującego głównego nurtu; jego automatyczne końce leżą po przeciwnych stronach środka, wzdłuż jego najdłuższej osi.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="309"/>
        <source>The polygon is a ring around one island: its centerline is the closed loop around the island, from and back to the ring&apos;s narrowest place. Give two split points for a line between them.</source>
        <translation>Poligon jest pierścieniem wokół jednej wyspy: jego linia środkowa to zamknięta pętla wokół wyspy, od najwęższego miejsca pierścienia i z powrotem do niego. Podaj dwa punkty podziału, by otrzymać linię między nimi.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="314"/>
        <source>The polygon is a ring around one island: its centerline is the closed loop around the island, from and back to the ring&apos;s narrowest place; the one split point given is not used. Give two split points for a line between them.</source>
        <translation>Poligon jest pierścieniem wokół jednej wyspy: jego linia środkowa to zamknięta pętla wokół wyspy, od najwęższego miejsca pierścienia i z powrotem do niego; podany jeden punkt podziału nie jest używany. Podaj dwa punkty podziału, by otrzymać linię między nimi.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="63"/>
        <source>The label option {name} must be a number ({what}), not {value!r}.</source>
        <translation>Opcja etykiety {name} musi być liczbą ({what}), a nie {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="66"/>
        <source>The label option {name} is {value!r}; it must be {what}.</source>
        <translation>Opcja etykiety {name} ma wartość {value!r}; musi to być {what}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="69"/>
        <source>a share of the widest width, at least 0 and under 1</source>
        <translation>ułamek największej szerokości, co najmniej 0 i poniżej 1</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="72"/>
        <source>a share of the local width, at least 0 and under 0.5 (the middle)</source>
        <translation>ułamek lokalnej szerokości, co najmniej 0 i poniżej 0,5 (środek)</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="75"/>
        <source>a share of the local width, at least 0</source>
        <translation>ułamek lokalnej szerokości, co najmniej 0</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="76"/>
        <source>a ratio, at least 0</source>
        <translation>stosunek, co najmniej 0</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="85"/>
        <source>{name} has {given} values for {count} geometries; give one value or one per geometry.</source>
        <translation>{name} ma {given} wartości dla {count} geometrii; podaj jedną wartość albo po jednej na geometrię.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="285"/>
        <source>The boundary this feature shares with the features it touches could not be computed ({reason}): it is not connected to them. Repair it first (e.g. QGIS &apos;{fix_geometries}&apos;).</source>
        <translation>Nie udało się wyznaczyć granicy, którą ten obiekt dzieli z obiektami, których dotyka ({reason}): nie jest z nimi połączony. Najpierw go napraw (np. narzędziem QGIS „{fix_geometries}”).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="44"/>
        <source>it needs 2 (or fewer, to find the missing ends automatically); with 3 or more ends (a confluence, or a reach touching 3 others) it is a network: compute its centerline network instead</source>
        <translation>potrzebne są 2 (albo mniej, by brakujące końce wyznaczyć automatycznie); przy 3 lub więcej końcach (zlewisko albo odcinek stykający się z 3 innymi) to sieć: wyznacz zamiast tego sieć osi</translation>
    </message>
</context>
<context>
    <name>IncirCuExpressions</name>
    <message>
        <location filename="../algorithms/expressions.py" line="286"/>
        <source>{} must be a number, not {!r}</source>
        <translation>{} musi być liczbą, a nie {!r}</translation>
    </message>
    <message>
        <location filename="../algorithms/expressions.py" line="295"/>
        <source>end_rule must be one of {}, not {!r}</source>
        <translation>end_rule musi być jednym z: {}, a nie {!r}</translation>
    </message>
    <message>
        <location filename="../algorithms/expressions.py" line="327"/>
        <source>&lt;h3&gt;incircu_centerline(geometry, tolerance, end_rule)&lt;/h3&gt;&lt;p&gt;The centerline of every part of a polygon (IncirCu&apos;s Curve of Incircles, between automatic ends), as a multi-line in the layer&apos;s CRS; NULL when no part has one. For a geometry generator symbol.&lt;/p&gt;&lt;h4&gt;Arguments&lt;/h4&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;geometry&lt;/b&gt;: a polygon, usually &lt;code&gt;$geometry&lt;/code&gt;.&lt;/li&gt;&lt;li&gt;&lt;b&gt;tolerance&lt;/b&gt; (optional): largest distance from the exact medial axis, layer units (metres for a layer in degrees); 0 or NULL: 1/200 of the typical width.&lt;/li&gt;&lt;li&gt;&lt;b&gt;end_rule&lt;/b&gt; (optional): &apos;main_stem&apos; (default) or &apos;longest_path&apos;.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Results are cached per geometry: panning and zooming do not recompute them.&lt;/p&gt;&lt;h4&gt;Example&lt;/h4&gt;&lt;p&gt;&lt;code&gt;incircu_centerline($geometry)&lt;/code&gt;&lt;/p&gt;</source>
        <translation>&lt;h3&gt;incircu_centerline(geometry, tolerance, end_rule)&lt;/h3&gt;&lt;p&gt;Linia środkowa każdej części poligonu (krzywa okręgów wpisanych IncirCu, między automatycznymi końcami) jako wielolinia w układzie warstwy; NULL, gdy żadna część jej nie ma. Do symbolu z generatorem geometrii.&lt;/p&gt;&lt;h4&gt;Argumenty&lt;/h4&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;geometry&lt;/b&gt;: poligon, zwykle &lt;code&gt;$geometry&lt;/code&gt;.&lt;/li&gt;&lt;li&gt;&lt;b&gt;tolerance&lt;/b&gt; (opcjonalny): największa odległość od dokładnej osi środkowej w jednostkach warstwy (w metrach dla warstwy w stopniach); 0 lub NULL: 1/200 typowej szerokości.&lt;/li&gt;&lt;li&gt;&lt;b&gt;end_rule&lt;/b&gt; (opcjonalny): 'main_stem' (domyślnie) lub 'longest_path'.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Wyniki są zapamiętywane dla każdej geometrii: przesuwanie i powiększanie mapy ich nie przelicza.&lt;/p&gt;&lt;h4&gt;Przykład&lt;/h4&gt;&lt;p&gt;&lt;code&gt;incircu_centerline($geometry)&lt;/code&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../algorithms/expressions.py" line="346"/>
        <source>&lt;h3&gt;incircu_label_line(geometry, trim, clearance, bend, min_elongation, smoothing, end_rule, points)&lt;/h3&gt;&lt;p&gt;The line a curved label of a lake or a wide river follows, as the &apos;Label lines of polygons&apos; algorithm computes it for the polygon&apos;s largest part: the main stem trimmed to where the polygon is at least &lt;i&gt;trim&lt;/i&gt; of its widest width, smoothed, at least &lt;i&gt;clearance&lt;/i&gt; local widths off the shore, bending no tighter than &lt;i&gt;bend&lt;/i&gt; local widths, reading from left to right. A compact part gives a label point (the centre of its largest incircle), or NULL when &lt;i&gt;points&lt;/i&gt; is false. Use it as the label&apos;s geometry generator with curved placement.&lt;/p&gt;&lt;h4&gt;Arguments&lt;/h4&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;geometry&lt;/b&gt;: a polygon, usually &lt;code&gt;$geometry&lt;/code&gt;.&lt;/li&gt;&lt;li&gt;&lt;b&gt;trim&lt;/b&gt;, &lt;b&gt;clearance&lt;/b&gt;, &lt;b&gt;bend&lt;/b&gt;, &lt;b&gt;min_elongation&lt;/b&gt;, &lt;b&gt;smoothing&lt;/b&gt; (optional): as in the algorithm; NULL: its defaults (0.5, 0.25, 0.5, 3, 0.5).&lt;/li&gt;&lt;li&gt;&lt;b&gt;end_rule&lt;/b&gt; (optional): &apos;main_stem&apos; (default) or &apos;longest_path&apos;.&lt;/li&gt;&lt;li&gt;&lt;b&gt;points&lt;/b&gt; (optional): true (default) to return a label point for compact parts.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Results are cached per geometry: panning and zooming do not recompute them.&lt;/p&gt;&lt;h4&gt;Example&lt;/h4&gt;&lt;p&gt;&lt;code&gt;incircu_label_line($geometry, points:=false)&lt;/code&gt;&lt;/p&gt;</source>
        <translation>&lt;h3&gt;incircu_label_line(geometry, trim, clearance, bend, min_elongation, smoothing, end_rule, points)&lt;/h3&gt;&lt;p&gt;Linia, wzdłuż której biegnie wygięta etykieta jeziora lub szerokiej rzeki, tak jak wyznacza ją algorytm 'Linie etykiet poligonów' dla największej części poligonu: główny nurt przycięty do miejsc, w których poligon ma co najmniej &lt;i&gt;trim&lt;/i&gt; swojej największej szerokości, wygładzony, co najmniej &lt;i&gt;clearance&lt;/i&gt; lokalnych szerokości od brzegu, wygięty nie ciaśniej niż &lt;i&gt;bend&lt;/i&gt; lokalnych szerokości, czytany od lewej do prawej. Zwarta część daje punkt etykiety (środek największego koła wpisanego) albo NULL, gdy &lt;i&gt;points&lt;/i&gt; jest fałszem. Użyj jej jako generatora geometrii etykiety z rozmieszczeniem zakrzywionym.&lt;/p&gt;&lt;h4&gt;Argumenty&lt;/h4&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;geometry&lt;/b&gt;: poligon, zwykle &lt;code&gt;$geometry&lt;/code&gt;.&lt;/li&gt;&lt;li&gt;&lt;b&gt;trim&lt;/b&gt;, &lt;b&gt;clearance&lt;/b&gt;, &lt;b&gt;bend&lt;/b&gt;, &lt;b&gt;min_elongation&lt;/b&gt;, &lt;b&gt;smoothing&lt;/b&gt; (opcjonalne): jak w algorytmie; NULL: jego wartości domyślne (0.5, 0.25, 0.5, 3, 0.5).&lt;/li&gt;&lt;li&gt;&lt;b&gt;end_rule&lt;/b&gt; (opcjonalny): 'main_stem' (domyślnie) lub 'longest_path'.&lt;/li&gt;&lt;li&gt;&lt;b&gt;points&lt;/b&gt; (opcjonalny): prawda (domyślnie), by zwracać punkt etykiety dla zwartych części.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Wyniki są zapamiętywane dla każdej geometrii: przesuwanie i powiększanie mapy ich nie przelicza.&lt;/p&gt;&lt;h4&gt;Przykład&lt;/h4&gt;&lt;p&gt;&lt;code&gt;incircu_label_line($geometry, points:=false)&lt;/code&gt;&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>LabelLinesAlgorithm</name>
    <message>
        <location filename="../algorithms/label_lines.py" line="47"/>
        <source>Label lines of polygons</source>
        <translation>Linie etykiet poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="50"/>
        <source>The line a curved lake or river name follows, or a label point for a round lake.</source>
        <translation>Linia, wzdłuż której biegnie wygięta nazwa jeziora lub rzeki, albo punkt etykiety dla okrągłego jeziora.</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="53"/>
        <source>Label lines</source>
        <translation>Linie etykiet</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="56"/>
        <source>Line layer: one label line per elongated polygon part, reading from left to right, with the input attributes plus source_fid, part, length, width_min (the narrowest width along the line: the tallest lettering that fits; layer units, metres for a layer in degrees), elongation and kind (line).</source>
        <translation>Warstwa liniowa: jedna linia etykiety na każdą wydłużoną część poligonu, czytana od lewej do prawej, z atrybutami wejściowymi oraz source_fid, part, length, width_min (najmniejsza szerokość wzdłuż linii: najwyższe mieszczące się litery; w jednostkach warstwy, w metrach dla warstwy w stopniach), elongation i kind (line).</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="64"/>
        <source>label,labels,lake,reservoir,river,name,curved,centerline,placement,cartography</source>
        <translation>etykieta,etykiety,jezioro,zbiornik,rzeka,nazwa,wygięta,linia środkowa,rozmieszczenie,kartografia</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="67"/>
        <source>Computes, for each polygon part, the line a curved label should follow: the main stem (as &apos;Centerline of polygons&apos; finds it, between split points, along guide lines or between automatic ends), trimmed at both ends to where the polygon is at least &apos;Trim&apos; times its widest width, smoothed so that it bends no tighter than &apos;Bend&apos; times the local width, and checked to keep &apos;Clearance&apos; times the local width off the shore at every segment (where it cannot, the longest piece that can is kept). Lines read from left to right (west to east; south to north when vertical). A part whose main stem is shorter than &apos;Minimum elongation&apos; times its mean width gets a label point instead: the centre of its largest incircle. Geographic layers are computed in a local metric projection; lengths are then in metres.</source>
        <translation>Wyznacza dla każdej części poligonu linię, wzdłuż której powinna biec wygięta etykieta: główny nurt (tak jak znajduje go 'Linia środkowa poligonów': między punktami podziału, wzdłuż linii prowadzących lub między automatycznymi końcami), przycięty z obu stron do miejsc, w których poligon ma co najmniej 'Przycięcie' razy swoją największą szerokość, wygładzony tak, by nie wyginał się ciaśniej niż 'Zgięcie' razy lokalna szerokość, i sprawdzony, czy każdy odcinek leży co najmniej 'Odstęp' razy lokalna szerokość od brzegu (gdzie to niemożliwe, zostaje najdłuższy fragment, który to spełnia). Linie czyta się od lewej do prawej (z zachodu na wschód; z południa na północ, gdy są pionowe). Część, której główny nurt jest krótszy niż 'Najmniejsze wydłużenie' razy jej średnia szerokość, dostaje zamiast tego punkt etykiety: środek największego koła wpisanego. Warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym; długości są wtedy w metrach.</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="82"/>
        <source>Trim: ends where the width falls below this share of the widest</source>
        <translation>Przycięcie: końce tam, gdzie szerokość spada poniżej tego ułamka największej</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="82"/>
        <source>Both ends of the main stem are cut back to the first and last point where the polygon is at least this share of its widest width: out of the narrow tips and bays. 0 keeps the whole main stem.</source>
        <translation>Oba końce głównego nurtu są skracane do pierwszego i ostatniego punktu, w którym poligon ma co najmniej ten ułamek swojej największej szerokości: poza wąskie końce i zatoki. 0 zachowuje cały główny nurt.</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="82"/>
        <source>Clearance from the shore, share of the local width</source>
        <translation>Odstęp od brzegu, ułamek lokalnej szerokości</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="82"/>
        <source>Every segment of a label line is at least this share of the local width away from the outline (0.25: the line keeps to the middle half).</source>
        <translation>Każdy odcinek linii etykiety leży co najmniej o ten ułamek lokalnej szerokości od obrysu (0,25: linia trzyma się środkowej połowy).</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="82"/>
        <source>Tightest bend: radius of curvature, share of the local width</source>
        <translation>Najciaśniejsze zgięcie: promień krzywizny, ułamek lokalnej szerokości</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="82"/>
        <source>The radius of curvature at every vertex is at least this share of the local width: a label bends gently where the lake is wide.</source>
        <translation>Promień krzywizny w każdym wierzchołku wynosi co najmniej ten ułamek lokalnej szerokości: etykieta wygina się łagodnie tam, gdzie jezioro jest szerokie.</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="82"/>
        <source>Minimum elongation for a line</source>
        <translation>Najmniejsze wydłużenie dla linii</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="82"/>
        <source>A part whose main-stem length over mean width (its area over that length) is below this gets a label point, the centre of its largest incircle (a disc: 1.27; a 3:1 ellipse: 3.8).</source>
        <translation>Część, której stosunek długości głównego nurtu do średniej szerokości (pola powierzchni przez tę długość) jest mniejszy, dostaje punkt etykiety, środek największego koła wpisanego (koło: 1,27; elipsa 3:1: 3,8).</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="82"/>
        <source>Smoothing, share of the local width</source>
        <translation>Wygładzanie, ułamek lokalnej szerokości</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="82"/>
        <source>Standard deviation of the Gaussian smoothing along the main stem, as a share of the local width; it is lowered where the line would come too near the shore and raised where it would bend too tightly.</source>
        <translation>Odchylenie standardowe wygładzania gaussowskiego wzdłuż głównego nurtu jako ułamek lokalnej szerokości; jest zmniejszane tam, gdzie linia zbliżyłaby się za bardzo do brzegu, i zwiększane tam, gdzie wygięłaby się zbyt ciasno.</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="149"/>
        <source>Label points</source>
        <translation>Punkty etykiet</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="149"/>
        <source>Point layer: one label point per compact polygon part (the centre of its largest incircle), with the same fields (length 0, width_min the incircle&apos;s diameter, kind point).</source>
        <translation>Warstwa punktowa: jeden punkt etykiety na każdą zwartą część poligonu (środek jej największego koła wpisanego), z tymi samymi polami (length 0, width_min średnica koła, kind point).</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="158"/>
        <source>Number of labels</source>
        <translation>Liczba etykiet</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="158"/>
        <source>Number of label lines and points written.</source>
        <translation>Liczba zapisanych linii i punktów etykiet.</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="176"/>
        <source>label lines</source>
        <translation>linie etykiet</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="176"/>
        <source>label points</source>
        <translation>punkty etykiet</translation>
    </message>
</context>
<context>
    <name>LinesCenterlineAlgorithm</name>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="53"/>
        <source>centerline,centreline,medial axis,banks,river,road,width,incircle</source>
        <translation>linia środkowa,oś,oś medialna,brzegi,rzeka,droga,szerokość,okrąg wpisany</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="74"/>
        <source>First lines (bank A)</source>
        <translation>Pierwsze linie (brzeg A)</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="81"/>
        <source>Second lines (bank B)</source>
        <translation>Drugie linie (brzeg B)</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="85"/>
        <source>Pairing field of the first lines</source>
        <translation>Pole parujące pierwszych linii</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="98"/>
        <source>Pairing field of the second lines</source>
        <translation>Pole parujące drugich linii</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="177"/>
        <source>{} holds no line.</source>
        <translation>{} nie zawiera żadnej linii.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="35"/>
        <source>Centerline between two lines</source>
        <translation>Linia środkowa między dwiema liniami</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="38"/>
        <source>One unbranched centerline between two lines, such as the two banks of a river.</source>
        <translation>Jedna nierozgałęziona linia środkowa między dwiema liniami, na przykład brzegami rzeki.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="41"/>
        <source>Centerline between lines</source>
        <translation>Linia środkowa między liniami</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="81"/>
        <source>Line layer of the other side; reprojected to the CRS of the first lines when needed.</source>
        <translation>Warstwa liniowa drugiej strony; w razie potrzeby przeliczana do układu pierwszych linii.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="98"/>
        <source>Optional; required together with &apos;Pairing field of the first lines&apos;.</source>
        <translation>Opcjonalne; wymagane razem z 'Pole parujące pierwszych linii'.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="44"/>
        <source>Line layer, one line per pair of lines: the attributes of the first lines plus source_fid (the id of the pair&apos;s first feature in the first lines), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive width; layer units, metres for a layer in degrees) and n_vertices. Its ends_found (always false) and ends_from (always empty) are there only so that it has the fields of &apos;Centerline of polygons&apos;.</source>
        <translation>Warstwa liniowa, jedna linia na parę linii: atrybuty pierwszych linii oraz source_fid (identyfikator pierwszego obiektu pary w pierwszych liniach), length, width_min, width_mean, width_max (średnice okręgów wpisanych w wierzchołkach o dodatniej szerokości; jednostki warstwy, metry dla warstwy w stopniach) i n_vertices. Pola ends_found (zawsze fałsz) i ends_from (zawsze puste) istnieją tylko po to, by warstwa miała pola algorytmu 'Linia środkowa poligonów'.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="74"/>
        <source>Line layer of one side; the output has its CRS and its attributes. Z values (of both layers) are ignored: the centerline is computed in the plane.</source>
        <translation>Warstwa liniowa jednej strony; wynik ma jej układ współrzędnych i atrybuty. Wartości Z (obu warstw) są pomijane: linia środkowa jest obliczana na płaszczyźnie.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="121"/>
        <source>Give both {} and {}, or neither (then each layer holds one line).</source>
        <translation>Podaj oba pola, {} i {}, albo żadnego (wtedy każda warstwa zawiera jedną linię).</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="180"/>
        <source>{} holds {} separate lines that do not join into one; give {} and {} to pair them, or merge them into one line.</source>
        <translation>{} zawiera linie, które nie łączą się w jedną (jest ich {}); podaj {} i {}, aby je sparować, albo scal je w jedną linię.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="166"/>
        <source>No line in {} has {} = {!r}; line {} of {} unused.</source>
        <translation>Żadna linia w {} nie ma {} = {!r}; linia {} z {} nie została użyta.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="195"/>
        <source>no line in {} has {} = {!r}</source>
        <translation>żadna linia w {} nie ma {} = {!r}</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="213"/>
        <source>the lines of {} with this pairing value do not join into one</source>
        <translation>linie z {} o tej wartości parowania nie łączą się w jedną</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="56"/>
        <source>Computes one unbranched centerline between two lines (for example the two banks of a river) with the Curve of Incircles: every vertex is the centre of a circle touching both lines. Lines are paired by equal values of the two pairing fields (or of a field both layers have); without them each layer holds one line (its features and parts are merged). The lines must not cross. The M value of each vertex is the local width. The second lines are reprojected to the CRS of the first; geographic layers are computed in a local metric projection and distances are then in metres.</source>
        <translation>Wyznacza jedną nierozgałęzioną linię środkową między dwiema liniami (na przykład dwoma brzegami rzeki) metodą Krzywej Okręgów Wpisanych: każdy wierzchołek jest środkiem okręgu stycznego do obu linii. Linie są łączone w pary według równych wartości obu pól parowania (lub pola, które mają obie warstwy); bez nich każda warstwa zawiera jedną linię (jej obiekty i części są scalane). Linie nie mogą się przecinać. Wartość M każdego wierzchołka to lokalna szerokość. Drugie linie są przeliczane do układu pierwszych; warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym i odległości są wtedy w metrach.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="85"/>
        <source>Optional; a line of the first lines is paired with the line of the second lines that has the same value in &apos;Pairing field of the second lines&apos;. Left empty, a field both layers have with values found in both pairs them (the log names it).</source>
        <translation>Opcjonalne; linia z pierwszych linii jest łączona w parę z linią z drugich linii o tej samej wartości w 'Pole parowania drugich linii'. Gdy puste, pary tworzy pole, które mają obie warstwy, o wartościach występujących w obu (dziennik je podaje).</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="149"/>
        <source>No pairing fields given: both layers have the field &apos;{}&apos;, so lines are paired by its values (give {} and {} to pair them otherwise).</source>
        <translation>Nie podano pól parowania: obie warstwy mają pole '{}', więc linie są łączone w pary według jego wartości (podaj {} i {}, by łączyć je inaczej).</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="56"/>
        <source>A line doubling back over itself (a zero-width spike, or an end coming back) loses that part first, with a warning naming where.</source>
        <translation>Linia zawracająca po sobie (kolec o zerowej szerokości albo cofający się koniec) najpierw traci tę część, z ostrzeżeniem wskazującym miejsce.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="108"/>
        <source>the middle of the gap between the two lines&apos; ends</source>
        <translation>środka przerwy między końcami obu linii</translation>
    </message>
</context>
<context>
    <name>PolygonCenterlineAlgorithm</name>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="65"/>
        <source>centerline,centreline,medial axis,skeleton,river,road,dike,width,incircle</source>
        <translation>linia środkowa,oś,oś medialna,szkielet,rzeka,droga,wał,szerokość,okrąg wpisany</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="102"/>
        <source>Polygon layer</source>
        <translation>Warstwa poligonowa</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="111"/>
        <source>Split points</source>
        <translation>Punkty podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="90"/>
        <source>One feature per polygon part</source>
        <translation>Jeden obiekt na każdą część poligonu</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="90"/>
        <source>Write one line feature per part of a multipart polygon instead of one MultiLineString per input feature.</source>
        <translation>Zapisz osobny obiekt liniowy dla każdej części poligonu wieloczęściowego zamiast jednego MultiLineString na obiekt wejściowy.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="48"/>
        <source>Centerline of polygons</source>
        <translation>Linia środkowa poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="51"/>
        <source>One unbranched centerline through each elongated polygon (river, road, dike).</source>
        <translation>Jedna nierozgałęziona linia środkowa każdego wydłużonego poligonu (rzeki, drogi, wału).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="54"/>
        <source>Centerlines of polygons</source>
        <translation>Linie środkowe poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="68"/>
        <source>Computes one unbranched, loop-free centerline for each polygon (each part of a multipart polygon) with the Curve of Incircles: every vertex is the centre of a circle touching both sides of the outline. The line runs between the two &apos;Split points&apos; lying on the polygon&apos;s outline, or, without them, between automatic ends: those of the internal path along the &apos;Guide lines&apos;, else of the main stem (or the longest internal path, see &apos;Automatic ends&apos;). Islands (holes) are passed on the side of the wider channel, or ignored. The M value of each vertex is the local width. Geographic layers are computed in a local metric projection; distances are then in metres. A polygon that cannot be processed is skipped with a warning naming its id and the reason.</source>
        <translation>Wyznacza jedną nierozgałęzioną linię środkową bez pętli dla każdego poligonu (każdej części poligonu wieloczęściowego) metodą Krzywej Okręgów Wpisanych: każdy wierzchołek jest środkiem okręgu stycznego do obu stron obrysu. Linia biegnie między dwoma 'Punktami podziału' leżącymi na obrysie poligonu, a bez nich między końcami automatycznymi: końcami drogi wewnątrz kształtu wzdłuż 'Linii prowadzących', a bez nich głównego nurtu (lub najdłuższej drogi wewnątrz kształtu, zob. 'Końce automatyczne'). Wyspy (otwory) są omijane od strony szerszego koryta albo pomijane. Wartość M każdego wierzchołka to lokalna szerokość. Warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym; odległości są wtedy w metrach. Poligon, którego nie da się przetworzyć, jest pomijany z ostrzeżeniem podającym jego identyfikator i przyczynę.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="135"/>
        <source>Automatic ends</source>
        <translation>Końce automatyczne</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="134"/>
        <source>Main stem (widest path)</source>
        <translation>Główny nurt (najszersza droga)</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="134"/>
        <source>Longest path</source>
        <translation>Najdłuższa droga</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="145"/>
        <source>Guide lines</source>
        <translation>Linie prowadzące</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="145"/>
        <source>Rough river lines (a national network, OpenStreetMap waterways) for polygons without split points: the ends are those of the internal path that best covers the guide lines near the polygon. Gaps, offsets, generalised pieces and tributaries are fine. Another CRS is reprojected.</source>
        <translation>Przybliżone linie rzek (sieć krajowa, cieki OpenStreetMap) dla poligonów bez punktów podziału: końcami są końce drogi wewnątrz kształtu, która najlepiej pokrywa linie prowadzące w pobliżu poligonu. Przerwy, przesunięcia, uogólnione fragmenty i dopływy nie przeszkadzają. Inny układ współrzędnych jest przeliczany.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="102"/>
        <source>Elongated polygons (rivers, roads, dikes); multipart polygons get one centerline per part. Z values are ignored: the centerline is computed in the plane.</source>
        <translation>Wydłużone poligony (rzeki, drogi, wały); poligony wieloczęściowe dostają jedną linię środkową na część. Wartości Z są pomijane: linia środkowa jest obliczana na płaszczyźnie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="127"/>
        <source>{pass_through}: the line never crosses an island and goes round it on the side of the wider channel. {ignore}: holes are filled before computing.</source>
        <translation>{pass_through}: linia nigdy nie przecina wyspy i omija ją od strony szerszego koryta. {ignore}: otwory są wypełniane przed obliczeniem.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="135"/>
        <source>For polygons without split points. {main_stem}: the internal path that sweeps the largest channel area (length times width), so a wide main river wins over a longer but narrow side arm. {longest_path}: the tips of the two longest arms.</source>
        <translation>Dla poligonów bez punktów podziału. {main_stem}: droga wewnątrz kształtu obejmująca największą powierzchnię koryta (długość razy szerokość), więc szeroka rzeka główna wygrywa z dłuższą, lecz wąską odnogą. {longest_path}: końce dwóch najdłuższych ramion.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="295"/>
        <source>0: a millionth of the polygon&apos;s size</source>
        <translation>0: jedna milionowa rozmiaru poligonu</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="274"/>
        <source>{} Its ends were found automatically.</source>
        <translation>{} Jego końce wyznaczono automatycznie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="297"/>
        <source>{} holds no point.</source>
        <translation>{} nie zawiera żadnego punktu.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="298"/>
        <source>no split point lies within {} of its outline, the {}; the nearest is {:.6g} {} away.</source>
        <translation>żaden punkt podziału nie leży w odległości {} od jego obrysu, czyli w granicach {}; najbliższy jest w odległości {:.6g} {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="193"/>
        <source>split points</source>
        <translation>punkty podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="195"/>
        <source>guide lines</source>
        <translation>linie prowadzące</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="196"/>
        <source>main stem</source>
        <translation>główny nurt</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="196"/>
        <source>longest path</source>
        <translation>najdłuższa droga</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="57"/>
        <source>Line layer: input attributes plus source_fid (the polygon&apos;s feature id, to join the line back to it), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive width; layer units, metres for a layer in degrees), n_vertices, ends_found (true when no split points were used) and ends_from (split_points, guide, automatic, or split_points_and_automatic for one given split point).</source>
        <translation>Warstwa liniowa: atrybuty wejściowe oraz source_fid (identyfikator obiektu poligonu, do połączenia linii z nim), length, width_min, width_mean, width_max (średnice okręgów wpisanych w wierzchołkach o dodatniej szerokości; jednostki warstwy, metry dla warstwy w stopniach), n_vertices, ends_found (prawda, gdy nie użyto punktów podziału) i ends_from (split_points, guide, automatic lub split_points_and_automatic dla jednego podanego punktu podziału).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="68"/>
        <source>A ring around one island (a roundabout, a moat, an atoll) gets, without split points, the closed loop around the island, from and back to its narrowest place. Zero-width spikes of the outline (going out and back along themselves) are removed first, with a warning naming where.</source>
        <translation>Pierścień wokół jednej wyspy (rondo, fosa, atol) otrzymuje bez punktów podziału zamkniętą pętlę wokół wyspy, od najwęższego miejsca pierścienia i z powrotem do niego. Kolce obrysu o zerowej szerokości (wychodzące i wracające po sobie) są najpierw usuwane, z ostrzeżeniem wskazującym miejsce.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="111"/>
        <source>Points marking where each centerline starts and ends: two per polygon part, within &apos;Split point snapping tolerance&apos; of its exterior ring. A part with none gets automatic ends; a part with one starts there and ends at the far end of its main stem; a part with more than two is skipped. Another CRS is reprojected to the polygon layer&apos;s.</source>
        <translation>Punkty wyznaczające początek i koniec każdej linii środkowej: dwa na część poligonu, w odległości nie większej niż 'Tolerancja przyciągania punktów podziału' od jej pierścienia zewnętrznego. Część bez punktów dostaje końce automatyczne; część z jednym zaczyna się w nim i kończy na dalszym końcu swojego głównego nurtu; część z więcej niż dwoma jest pomijana. Inny układ współrzędnych jest przeliczany do układu warstwy poligonowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="89"/>
        <source>the split point, or for automatic ends where that line meets the outline</source>
        <translation>punktu podziału, a dla końców automatycznych do miejsca, w którym ta prosta przecina obrys</translation>
    </message>
</context>
<context>
    <name>PolygonNetworkAlgorithm</name>
    <message>
        <location filename="../algorithms/polygon_network.py" line="50"/>
        <source>Centerline network of polygons</source>
        <translation>Sieć linii środkowych poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="53"/>
        <source>The medial-axis tree between the arm ends of a confluence, a delta or a road junction.</source>
        <translation>Drzewo osi środkowej między końcami ramion zlewiska, delty lub skrzyżowania dróg.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="57"/>
        <source>Network branches</source>
        <translation>Gałęzie sieci</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="60"/>
        <source>network,confluence,delta,junction,crossing,medial axis,skeleton,river,road,width</source>
        <translation>sieć,zlewisko,delta,węzeł,skrzyżowanie,oś środkowa,szkielet,rzeka,droga,szerokość</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="91"/>
        <source>Polygon layer</source>
        <translation>Warstwa poligonowa</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="100"/>
        <source>Split points</source>
        <translation>Punkty podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="111"/>
        <source>Split point id field</source>
        <translation>Pole identyfikatora punktu podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="111"/>
        <source>Attribute naming each split point in from_point, to_point and the chains; default: its feature id.</source>
        <translation>Atrybut nazywający każdy punkt podziału w from_point, to_point i łańcuchach; domyślnie: identyfikator obiektu.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="194"/>
        <source>Number of branches</source>
        <translation>Liczba gałęzi</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="194"/>
        <source>Number of branch features written.</source>
        <translation>Liczba zapisanych obiektów gałęzi.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="91"/>
        <source>Polygons with several arms (confluences, deltas, road junctions); each part gets its network. Z values are ignored: the network is computed in the plane.</source>
        <translation>Poligony z kilkoma ramionami (zlewiska, delty, skrzyżowania dróg); każda część dostaje swoją sieć. Wartości Z są pomijane: sieć jest obliczana na płaszczyźnie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="197"/>
        <source>centerline network</source>
        <translation>sieć linii środkowych</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="63"/>
        <source>Zero-width spikes of the outline (going out and back along themselves) are removed first, with a warning naming where.</source>
        <translation>Kolce obrysu o zerowej szerokości (wychodzące i wracające po sobie) są najpierw usuwane, z ostrzeżeniem wskazującym miejsce.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="100"/>
        <source>The ends of the network, within &apos;Split point snapping tolerance&apos; of a part&apos;s exterior ring, typically one across each arm&apos;s end. A part with two or more uses exactly these; a part with none or one gets its arm ends automatically (the one given replaces the automatic end nearest to it, when within that arm&apos;s width). Another CRS is reprojected to the polygon layer&apos;s.</source>
        <translation>Końce sieci, w odległości nie większej niż 'Tolerancja przyciągania punktów podziału' od pierścienia zewnętrznego części, zwykle po jednym w poprzek końca każdego ramienia. Część z dwoma lub więcej używa dokładnie ich; część bez punktu lub z jednym dostaje końce ramion automatycznie (podany punkt zastępuje najbliższy mu koniec automatyczny, jeśli leży w obrębie szerokości tego ramienia). Inny układ współrzędnych jest przeliczany do układu warstwy poligonowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="124"/>
        <source>{pass_through}: no branch crosses an island; each island belongs to the chain it is nearer to, so the branches go round it on the side of the wider channel. {ignore}: holes are filled before computing. {channels}: every island at least as long as the river around it is wide (its own width plus twice its distance to the nearest bank or island) gets a branch on each side, so the network has a loop around it with exact junctions up- and downstream (branches of kind &apos;loop&apos;); smaller islands are passed on the side of the wider channel.</source>
        <translation>{pass_through}: żadna gałąź nie przecina wyspy; każda wyspa należy do łańcucha, do którego jest bliżej, więc gałęzie omijają ją po stronie szerszego koryta. {ignore}: otwory są wypełniane przed obliczeniem. {channels}: każda wyspa co najmniej tak długa, jak szeroka jest rzeka wokół niej (jej własna szerokość plus dwukrotna odległość do najbliższego brzegu lub wyspy), dostaje gałąź z każdej strony, więc sieć ma wokół niej pętlę z dokładnymi węzłami powyżej i poniżej (gałęzie rodzaju 'loop'); mniejsze wyspy są omijane po stronie szerszego koryta.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="136"/>
        <source>the split point (junctions are left as they are)</source>
        <translation>punktu podziału (węzły pozostają bez zmian)</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="137"/>
        <source>Minimum arm length, in junction widths</source>
        <translation>Minimalna długość ramienia, w szerokościach węzła</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="137"/>
        <source>Automatic ends: an arm is kept when it reaches beyond the circle of the junction it leaves by at least this many widths of that junction (1: bank bumps, digitising steps and bays shallower than the river is wide make no branch; a tributary does).</source>
        <translation>Końce automatyczne: ramię zostaje, gdy sięga poza okrąg węzła, od którego odchodzi, o co najmniej tyle szerokości tego węzła (1: garby brzegu, schodki digitalizacji i zatoki płytsze niż szerokość rzeki nie tworzą gałęzi; dopływ tworzy).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="151"/>
        <source>Minimum arm length</source>
        <translation>Minimalna długość ramienia</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="151"/>
        <source>Automatic ends: an arm is kept only when it also reaches at least this far beyond its junction&apos;s circle, layer units (metres for a layer in degrees); 0 = no such limit. For generalisation.</source>
        <translation>Końce automatyczne: ramię zostaje tylko wtedy, gdy sięga też co najmniej tak daleko poza okrąg swojego węzła, w jednostkach warstwy (metry dla warstwy w stopniach); 0 = bez takiego ograniczenia. Do generalizacji.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="167"/>
        <source>Line layer, one feature per branch: input attributes plus source_fid (the polygon&apos;s feature id, to join the branch back to it), from_point, to_point (split point ids, &apos;gate&apos;, &apos;auto&apos; or &apos;junction&apos;), from_node, to_node (node ids shared by the branches that meet, also across polygons whose ends coincide), kind (arm, inner or loop), right_chain, left_chain (each chain named &apos;a-b&apos; after the ends at its ends, counter-clockwise), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive width; layer units, metres for a layer in degrees) and n_vertices.</source>
        <translation>Warstwa liniowa, jeden obiekt na gałąź: atrybuty wejściowe oraz source_fid (identyfikator obiektu poligonu, do połączenia gałęzi z nim), from_point, to_point (identyfikatory punktów podziału, 'gate', 'auto' lub 'junction'), from_node, to_node (identyfikatory węzłów wspólne dla spotykających się gałęzi, także między poligonami o wspólnych końcach), kind (arm, inner lub loop), right_chain, left_chain (każdy łańcuch nazwany 'a-b' od końców na jego krańcach, przeciwnie do ruchu wskazówek zegara), length, width_min, width_mean, width_max (średnice okręgów wpisanych w wierzchołkach o dodatniej szerokości; jednostki warstwy, metry dla warstwy w stopniach) i n_vertices.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="181"/>
        <source>Network nodes</source>
        <translation>Węzły sieci</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="181"/>
        <source>Optional point layer: every end and junction with its node id, degree (number of branch ends), radius (the junction&apos;s circle; 0 at an end) and kind (end or junction).</source>
        <translation>Opcjonalna warstwa punktowa: każdy koniec i węzeł z identyfikatorem węzła, stopniem (liczbą końców gałęzi), promieniem (okręgu węzła; 0 na końcu) i rodzajem (end lub junction).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="63"/>
        <source>Computes, for each polygon (each part of a multipart polygon), lines down the middle of its arms (the arms of a confluence, a lake, a delta or a road junction), joined where the arms meet. The ends cut the outline into pieces, the chains; each line runs through the centres of circles touching two chains, a path of the shape&apos;s medial axis (the line of the centres of all circles touching two sides): a tree with one end at each arm and junctions where a circle touches three chains, without side branches. The ends are the &apos;Split points&apos; on the outline when a part has two or more; otherwise they are found automatically (one given split point replaces the automatic end nearest to it): an arm counts when it reaches beyond the circle of the junction it leaves by at least &apos;Minimum arm length, in junction widths&apos; (bank noise and small bays do not). Each branch is one line feature with its node ids (from_node, to_node, shared by the branches that meet), its kind, the ids of the split points at its ends (&apos;gate&apos; at a gate, &apos;auto&apos; at an automatic end, &apos;junction&apos; at a junction), the chains on its right and left, its length and widths; the M value of each vertex is the local width. Two split points give exactly the polygon centerline. Islands (holes) are passed on the side of the wider channel, or ignored. Geographic layers are computed in a local metric projection; distances are then in metres. A polygon that cannot be processed is skipped with a warning naming its id and the reason.</source>
        <translation>Wyznacza dla każdego poligonu (każdej części poligonu wieloczęściowego) linie biegnące środkiem jego ramion (ramion zlewiska, jeziora, delty lub skrzyżowania dróg), połączone tam, gdzie ramiona się spotykają. Końce dzielą obrys na odcinki, łańcuchy; każda linia biegnie przez środki okręgów stykających się z dwoma łańcuchami, po fragmencie osi środkowej kształtu (linii środków wszystkich okręgów stykających się z dwoma bokami): drzewo z jednym końcem w każdym ramieniu i węzłami tam, gdzie okrąg styka się z trzema łańcuchami, bez bocznych odgałęzień. Końcami są 'Punkty podziału' na obrysie, gdy część ma ich dwa lub więcej; w przeciwnym razie są wyznaczane automatycznie (jeden podany punkt podziału zastępuje najbliższy mu koniec automatyczny): ramię się liczy, gdy sięga poza okrąg węzła, od którego odchodzi, o co najmniej 'Minimalna długość ramienia, w szerokościach węzła' (szum brzegu i małe zatoki nie sięgają). Każda gałąź to jeden obiekt liniowy z identyfikatorami węzłów (from_node, to_node, wspólnymi dla gałęzi, które się spotykają), rodzajem, identyfikatorami punktów podziału na końcach ('gate' przy bramie, 'auto' przy końcu automatycznym, 'junction' w węźle), łańcuchami po prawej i lewej, długością i szerokościami; wartość M każdego wierzchołka to lokalna szerokość. Dwa punkty podziału dają dokładnie linię środkową poligonu. Wyspy (otwory) są omijane po stronie szerszego koryta albo pomijane. Warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym; odległości są wtedy w metrach. Poligon, którego nie da się przetworzyć, jest pomijany z ostrzeżeniem podającym jego identyfikator i przyczynę.</translation>
    </message>
</context>
<context>
    <name>SharedParameters</name>
    <message>
        <location filename="../algorithms/parameters.py" line="91"/>
        <source>Parameters</source>
        <translation>Parametry</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="91"/>
        <source>Advanced parameters</source>
        <translation>Parametry zaawansowane</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="91"/>
        <source>Outputs</source>
        <translation>Wyniki</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="162"/>
        <source>Largest deviation from the exact medial axis (0 = automatic)</source>
        <translation>Największe odchylenie od dokładnej osi środkowej (0 = automatycznie)</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="162"/>
        <source>Every vertex is the centre of a circle touching both sides; the line of the centres of all such circles is the exact medial axis. This is the largest distance between the centerline and that axis, in layer units (metres for a layer in degrees): the line keeps only the vertices it needs to stay that close, each lying exactly on the axis, and never leaves the shape whatever the value. 0 uses 1/200 of the shape&apos;s typical width: the right choice for maps. It may differ per feature (data-defined).</source>
        <translation>Każdy wierzchołek jest środkiem okręgu stycznego do obu stron; linia środków wszystkich takich okręgów to dokładna oś środkowa. To największa odległość linii środkowej od tej osi, w jednostkach warstwy (metry dla warstwy w stopniach): linia zachowuje tylko wierzchołki potrzebne, by pozostać tak blisko, każdy leżący dokładnie na osi, i niezależnie od wartości nigdy nie wychodzi poza kształt. 0 oznacza 1/200 typowej szerokości kształtu: właściwy wybór dla map. Może być inna dla każdego obiektu (wartość definiowana danymi).</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="175"/>
        <source>Fixed boundary sampling distance (0 = adaptive)</source>
        <translation>Stały odstęp próbkowania brzegu (0 = adaptacyjnie)</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="175"/>
        <source>The paper&apos;s fixed sampling: a sample every this distance along both sides, in layer units (metres for a layer in degrees), giving many evenly spaced vertices. Use it to reproduce the paper or for a dense line; 0 uses the adaptive sampling bounded by the largest deviation. Give either this or the largest deviation, not both.</source>
        <translation>Stałe próbkowanie z artykułu: próbka co tę odległość wzdłuż obu stron, w jednostkach warstwy (metry dla warstwy w stopniach), dające wiele równomiernie rozmieszczonych wierzchołków. Do odtworzenia artykułu lub gęstej linii; 0 oznacza próbkowanie adaptacyjne ograniczone największym odchyleniem. Podaj to albo największe odchylenie, nie oba.</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="190"/>
        <source>Split point snapping tolerance</source>
        <translation>Tolerancja przyciągania punktów podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="190"/>
        <source>Largest distance between a split point and the polygon&apos;s exterior ring, layer units (metres for a layer in degrees); 0 = a millionth of the polygon&apos;s size. It may differ per feature (data-defined).</source>
        <translation>Największa odległość punktu podziału od zewnętrznego pierścienia poligonu, w jednostkach warstwy (metry dla warstwy w stopniach); 0 = jedna milionowa rozmiaru poligonu. Może być inna dla każdego obiektu (wartość definiowana danymi).</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="217"/>
        <source>Pass through the main channel</source>
        <translation>Prowadź głównym korytem</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="217"/>
        <source>Ignore islands</source>
        <translation>Pomijaj wyspy</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="220"/>
        <source>Channels on both sides of large islands</source>
        <translation>Koryta po obu stronach dużych wysp</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="221"/>
        <source>Islands (holes)</source>
        <translation>Wyspy (otwory)</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="228"/>
        <source>Connect features that share a boundary</source>
        <translation>Połącz obiekty o wspólnej granicy</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="228"/>
        <source>Where two polygons of the layer share a stretch of boundary (a river cut into reaches, water or road-area pieces), the middle of that stretch becomes an end of both, so their lines meet there exactly (and, in a network, share the node id). A polygon with one such gate gets its other end(s) automatically.</source>
        <translation>Gdzie dwa poligony warstwy mają wspólny odcinek granicy (rzeka pocięta na odcinki, kawałki wód lub powierzchni dróg), środek tego odcinka staje się końcem obu, więc ich linie spotykają się tam dokładnie (a w sieci mają wspólny identyfikator węzła). Poligon z jedną taką bramą dostaje pozostałe końce automatycznie.</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="250"/>
        <source>Straight run-out (for maps)</source>
        <translation>Prosto wzdłuż osi koryta (do map)</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="250"/>
        <source>Exact medial axis</source>
        <translation>Dokładna oś środkowa</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="251"/>
        <source>Line ends</source>
        <translation>Końce linii</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="251"/>
        <source>How the line reaches its ends where the channel is cut at a slant. {runout}: straight on along the channel&apos;s axis from where the channel is first full width to {where}; its vertices there are not on the medial axis (their widths are interpolated). {axis}: the exact middle of the shape, which leaves a slanted end square to it and then bends onto the channel&apos;s axis.</source>
        <translation>Jak linia dochodzi do swoich końców tam, gdzie koryto jest ucięte ukośnie. {runout}: prosto dalej wzdłuż osi koryta od miejsca, w którym koryto po raz pierwszy ma pełną szerokość, do {where}; jej wierzchołki na tym odcinku nie leżą na osi środkowej (ich szerokości są interpolowane). {axis}: dokładny środek kształtu, który odchodzi od ukośnego końca prostopadle do niego, a potem skręca na oś koryta.</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="263"/>
        <source>Store the local width as M value</source>
        <translation>Zapisz lokalną szerokość jako wartość M</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="263"/>
        <source>Write the incircle diameter (local width, layer units or metres) as M value of each vertex.</source>
        <translation>Zapisz średnicę okręgu wpisanego (lokalną szerokość, w jednostkach warstwy lub metrach) jako wartość M każdego wierzchołka.</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="281"/>
        <source>Centerline vertices</source>
        <translation>Wierzchołki linii środkowej</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="281"/>
        <source>Optional point layer: every centerline vertex with its chainage, incircle radius and width.</source>
        <translation>Opcjonalna warstwa punktowa: każdy wierzchołek linii środkowej z kilometrażem, promieniem okręgu wpisanego i szerokością.</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="281"/>
        <source>Incircles</source>
        <translation>Okręgi wpisane</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="281"/>
        <source>Optional polygon layer: the incircle of every vertex, with its radius and chainage.</source>
        <translation>Opcjonalna warstwa poligonowa: okrąg wpisany każdego wierzchołka z promieniem i kilometrażem.</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="281"/>
        <source>Transects</source>
        <translation>Przekroje poprzeczne</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="281"/>
        <source>Optional line layer: cross-sections from bank to bank through the centerline, one every &apos;Distance between transects&apos;, with their width, chainage and method (their &apos;Transect shape&apos;: straight or nearest).</source>
        <translation>Opcjonalna warstwa liniowa: przekroje poprzeczne od brzegu do brzegu przez linię środkową, jeden co 'Odległość między przekrojami', z szerokością, kilometrażem i metodą (ich 'Kształt przekroju': straight lub nearest).</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="310"/>
        <source>Distance between transects (0 = mean width)</source>
        <translation>Odległość między przekrojami (0 = średnia szerokość)</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="310"/>
        <source>Distance along the centerline between two transects, layer units (metres for a layer in degrees); 0 uses the mean width of each centerline. It may differ per feature (data-defined).</source>
        <translation>Odległość wzdłuż linii środkowej między dwoma przekrojami, w jednostkach warstwy (metry dla warstwy w stopniach); 0 oznacza średnią szerokość każdej linii środkowej. Może być inna dla każdego obiektu (wartość definiowana danymi).</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="320"/>
        <source>Straight, square to the centerline</source>
        <translation>Prosty, prostopadły do linii środkowej</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="320"/>
        <source>To the nearest bank points</source>
        <translation>Do najbliższych punktów brzegów</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="321"/>
        <source>Transect shape</source>
        <translation>Kształt przekroju</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="321"/>
        <source>{straight}: one straight cross-section square to the centerline&apos;s direction, smoothed over about one width, from where it first meets a bank or island on one side to the other: what is surveyed in the field; its width is its length, at least the local width (method &apos;straight&apos;). {nearest}: from the centerline to the nearest point of each bank, the incircle&apos;s diameter; it bends at the centerline where the banks are not parallel (method &apos;nearest&apos;).</source>
        <translation>{straight}: jeden prosty przekrój prostopadły do kierunku linii środkowej, wygładzonego na długości około jednej szerokości, od miejsca, w którym po jednej stronie pierwszy raz napotyka brzeg lub wyspę, do takiego samego miejsca po drugiej stronie: taki, jaki mierzy się w terenie; jego szerokość to jego długość, nie mniejsza niż lokalna szerokość (metoda 'straight'). {nearest}: od linii środkowej do najbliższego punktu każdego brzegu, czyli średnica okręgu wpisanego; załamuje się na linii środkowej tam, gdzie brzegi nie są równoległe (metoda 'nearest').</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="333"/>
        <source>Number of centerlines</source>
        <translation>Liczba linii środkowych</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="333"/>
        <source>Number of centerline features written.</source>
        <translation>Liczba zapisanych obiektów linii środkowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="338"/>
        <source>Number of skipped features</source>
        <translation>Liczba pominiętych obiektów</translation>
    </message>
    <message>
        <location filename="../algorithms/parameters.py" line="338"/>
        <source>Number of input features (or parts) skipped with a warning.</source>
        <translation>Liczba obiektów wejściowych (lub ich części) pominiętych z ostrzeżeniem.</translation>
    </message>
</context>
</TS>
