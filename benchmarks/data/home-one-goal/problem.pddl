(define (problem home-1)
  (:domain assisted_living)
  (:objects
    robot1 - robot
    robot2 - robot
    robot3 - robot
    robot4 - robot
    senior1 - senior
    senior2 - senior
    senior3 - senior
    senior4 - senior
    senior5 - senior
    senior6 - senior
    senior7 - senior
    senior8 - senior
    senior9 - senior
    senior10 - senior
    senior11 - senior
    senior12 - senior
    senior13 - senior
    senior14 - senior
    senior15 - senior
    senior16 - senior
    senior17 - senior
    senior18 - senior
    senior19 - senior
    senior20 - senior
    senior21 - senior
    senior22 - senior
    senior23 - senior
    senior24 - senior
    senior25 - senior
    senior26 - senior
    senior27 - senior
    senior28 - senior
    senior29 - senior
    senior30 - senior
    senior31 - senior
    senior32 - senior
    senior33 - senior
    senior34 - senior
    senior35 - senior
    senior36 - senior
    senior37 - senior
    senior38 - senior
    senior39 - senior
    senior40 - senior
    corridor1 - corridor
    corridor2 - corridor
    corridor3 - corridor
    corridor4 - corridor
    corridor5 - corridor
    corridor6 - corridor
    corridor7 - corridor
    corridor8 - corridor
    corridor9 - corridor
    corridor10 - corridor
    corridor11 - corridor
    corridor12 - corridor
    corridor13 - corridor
    kitchen1 - kitchen
    dinning_room1 - dinning_room
    music_room1 - music_room
    library1 - library
    sunroom1 - sunroom
    sunroom2 - sunroom
    bedroom1 - bedroom
    sunroom3 - sunroom
    bedroom2 - bedroom
    bedroom3 - bedroom
    bedroom4 - bedroom
    sunroom4 - sunroom
    bedroom5 - bedroom
    bedroom6 - bedroom
    sunroom5 - sunroom
    bedroom7 - bedroom
    bedroom8 - bedroom
    sunroom6 - sunroom
    bedroom9 - bedroom
    sunroom7 - sunroom
    bedroom10 - bedroom
    bedroom11 - bedroom
    bedroom12 - bedroom
    bedroom13 - bedroom
    bedroom14 - bedroom
    bedroom15 - bedroom
    bedroom16 - bedroom
    bedroom17 - bedroom
    bedroom18 - bedroom
    sunroom8 - sunroom
    sunroom9 - sunroom
    sunroom10 - sunroom
    bedroom19 - bedroom
    bedroom20 - bedroom
    bedroom21 - bedroom
    bedroom22 - bedroom
    bedroom23 - bedroom
    bedroom24 - bedroom
    sunroom11 - sunroom
    bedroom25 - bedroom
    bedroom26 - bedroom
    bedroom27 - bedroom
    sunroom12 - sunroom
    bedroom28 - bedroom
    bedroom29 - bedroom
    bedroom30 - bedroom
    bedroom31 - bedroom
    sunroom13 - sunroom
    bedroom32 - bedroom
    bedroom33 - bedroom
    glass_id01 - drinking_glass
    bottle_id01 - glass_bottle
    violin_id01 - violin
    guitar_id01 - guitar
    book_id01 - book
    magazine_id01 - magazine
    puzzle_id01 - puzzle
    tv_id01 - tv
    pc_id01 - desktop
    guitar_id02 - guitar
    book_id02 - book
    pc_id02 - desktop
    puzzle_id02 - puzzle
    pc_id03 - desktop
    tv_id02 - tv
    guitar_id03 - guitar
    guitar_id04 - guitar
    magazine_id02 - magazine
    guitar_id05 - guitar
    bottle_id02 - glass_bottle
    violin_id02 - violin
    puzzle_id03 - puzzle
    puzzle_id04 - puzzle
    bottle_id03 - glass_bottle
    guitar_id06 - guitar
    book_id03 - book
    puzzle_id05 - puzzle
    book_id04 - book
    tv_id03 - tv
    violin_id03 - violin
    glass_id02 - drinking_glass
    tv_id04 - tv
    pc_id04 - desktop
    glass_id03 - drinking_glass
    tv_id05 - tv
    violin_id04 - violin
    magazine_id03 - magazine
    pc_id05 - desktop
    book_id05 - book
    pc_id06 - desktop
    bottle_id04 - glass_bottle
    tv_id06 - tv
    bottle_id05 - glass_bottle
    glass_id04 - drinking_glass
    violin_id05 - violin
    bottle_id06 - glass_bottle
    glass_id05 - drinking_glass
    pc_id07 - desktop
    bottle_id07 - glass_bottle
    pc_id08 - desktop
    violin_id06 - violin
    glass_id06 - drinking_glass
    puzzle_id06 - puzzle
    violin_id07 - violin
    bottle_id08 - glass_bottle
    book_id06 - book
    tv_id07 - tv
    guitar_id07 - guitar
    pc_id09 - desktop
    magazine_id04 - magazine
    puzzle_id07 - puzzle
    book_id07 - book
    pc_id10 - desktop
    magazine_id05 - magazine
    tv_id08 - tv
    magazine_id06 - magazine
    bottle_id09 - glass_bottle
    puzzle_id08 - puzzle
    puzzle_id09 - puzzle
    guitar_id08 - guitar
    pc_id11 - desktop
    guitar_id09 - guitar
    puzzle_id10 - puzzle
    book_id08 - book
    pc_id12 - desktop
    book_id09 - book
    guitar_id10 - guitar
    bottle_id10 - glass_bottle
    guitar_id11 - guitar
    violin_id08 - violin
    pc_id13 - desktop
    violin_id09 - violin
    guitar_id12 - guitar
    book_id10 - book
    bottle_id11 - glass_bottle
    puzzle_id11 - puzzle
    violin_id10 - violin
    bottle_id12 - glass_bottle
    violin_id11 - violin
    book_id11 - book
    puzzle_id12 - puzzle
    guitar_id13 - guitar
    tv_id09 - tv
    magazine_id07 - magazine
    guitar_id14 - guitar
    bottle_id13 - glass_bottle
    book_id12 - book
    glass_id07 - drinking_glass
    puzzle_id13 - puzzle
    book_id13 - book
    guitar_id15 - guitar
    magazine_id08 - magazine
    violin_id12 - violin
    guitar_id16 - guitar
    book_id14 - book
    puzzle_id14 - puzzle
    bottle_id14 - glass_bottle
    book_id15 - book
    magazine_id09 - magazine
    pc_id14 - desktop
    violin_id13 - violin
    tv_id10 - tv
    puzzle_id15 - puzzle
    book_id16 - book
    guitar_id17 - guitar
    magazine_id10 - magazine
    guitar_id18 - guitar
    book_id17 - book
    puzzle_id16 - puzzle
    tv_id11 - tv
    bottle_id15 - glass_bottle
    tv_id12 - tv
    pc_id15 - desktop
    bottle_id16 - glass_bottle
    glass_id08 - drinking_glass
    puzzle_id17 - puzzle
    glass_id09 - drinking_glass
    violin_id14 - violin
    book_id18 - book
    book_id19 - book
    pc_id16 - desktop
    puzzle_id18 - puzzle
    tv_id13 - tv
    violin_id15 - violin
    magazine_id11 - magazine
    magazine_id12 - magazine
    book_id20 - book
    glass_id10 - drinking_glass
    glass_id11 - drinking_glass
    book_id21 - book
    guitar_id19 - guitar
    pc_id17 - desktop
    book_id22 - book
    book_id23 - book
    violin_id16 - violin
    magazine_id13 - magazine
    guitar_id20 - guitar
    tv_id14 - tv
    magazine_id14 - magazine
    violin_id17 - violin
    pc_id18 - desktop
    bottle_id17 - glass_bottle
    magazine_id15 - magazine
    book_id24 - book
    magazine_id16 - magazine
    glass_id12 - drinking_glass
    book_id25 - book
    tv_id15 - tv
    violin_id18 - violin
    glass_id13 - drinking_glass
    book_id26 - book
    puzzle_id19 - puzzle
    book_id27 - book
    book_id28 - book
    book_id29 - book
    pc_id19 - desktop
    bottle_id18 - glass_bottle
    bottle_id19 - glass_bottle
    magazine_id17 - magazine
    puzzle_id20 - puzzle
    magazine_id18 - magazine
    book_id30 - book
    magazine_id19 - magazine
    glass_id14 - drinking_glass
    magazine_id20 - magazine
    guitar_id21 - guitar
    tv_id16 - tv
    violin_id19 - violin
    puzzle_id21 - puzzle
    guitar_id22 - guitar
    magazine_id21 - magazine
    pc_id20 - desktop
    violin_id20 - violin
    magazine_id22 - magazine
    book_id31 - book
    book_id32 - book
    bottle_id20 - glass_bottle
    glass_id15 - drinking_glass
    book_id33 - book
    guitar_id23 - guitar
    magazine_id23 - magazine
    book_id34 - book
    bottle_id21 - glass_bottle
    pc_id21 - desktop
    book_id35 - book
    bottle_id22 - glass_bottle
    puzzle_id22 - puzzle
    magazine_id24 - magazine
    book_id36 - book
    magazine_id25 - magazine
    glass_id16 - drinking_glass
    tv_id17 - tv
    magazine_id26 - magazine
    pc_id22 - desktop
    book_id37 - book
    puzzle_id23 - puzzle
    bottle_id23 - glass_bottle
    violin_id21 - violin
    bottle_id24 - glass_bottle
    glass_id17 - drinking_glass
    book_id38 - book
    magazine_id27 - magazine
    glass_id18 - drinking_glass
    glass_id19 - drinking_glass
    pc_id23 - desktop
    violin_id22 - violin
    guitar_id24 - guitar
    glass_id20 - drinking_glass
    book_id39 - book
    magazine_id28 - magazine
    bottle_id25 - glass_bottle
    puzzle_id24 - puzzle
    guitar_id25 - guitar
    tv_id18 - tv
    magazine_id29 - magazine
    pc_id24 - desktop
    book_id40 - book
    tv_id19 - tv
    magazine_id30 - magazine
    glass_id21 - drinking_glass
    violin_id23 - violin
    tv_id20 - tv
    pc_id25 - desktop
    glass_id22 - drinking_glass
    magazine_id31 - magazine
    guitar_id26 - guitar
    glass_id23 - drinking_glass
    tv_id21 - tv
    magazine_id32 - magazine
    bottle_id26 - glass_bottle
    puzzle_id25 - puzzle
    pc_id26 - desktop
    bottle_id27 - glass_bottle
    bottle_id28 - glass_bottle
    pc_id27 - desktop
    guitar_id27 - guitar
    book_id41 - book
    puzzle_id26 - puzzle
    pc_id28 - desktop
    pc_id29 - desktop
    bottle_id29 - glass_bottle
    tv_id22 - tv
    magazine_id33 - magazine
    violin_id24 - violin
    guitar_id28 - guitar
    pc_id30 - desktop
    book_id42 - book
    puzzle_id27 - puzzle
    violin_id25 - violin
    glass_id24 - drinking_glass
    bottle_id30 - glass_bottle
    puzzle_id28 - puzzle
    pc_id31 - desktop
    puzzle_id29 - puzzle
    pc_id32 - desktop
    pc_id33 - desktop
    puzzle_id30 - puzzle
    bottle_id31 - glass_bottle
    glass_id25 - drinking_glass
    book_id43 - book
    tv_id23 - tv
    magazine_id34 - magazine
    guitar_id29 - guitar
    guitar_id30 - guitar
    guitar_id31 - guitar
    magazine_id35 - magazine
    pc_id34 - desktop
    pc_id35 - desktop
    puzzle_id31 - puzzle
    magazine_id36 - magazine
    glass_id26 - drinking_glass
    magazine_id37 - magazine
    bottle_id32 - glass_bottle
    violin_id26 - violin
    violin_id27 - violin
    book_id44 - book
    glass_id27 - drinking_glass
    guitar_id32 - guitar
    pc_id36 - desktop
    violin_id28 - violin
    glass_id28 - drinking_glass
    puzzle_id32 - puzzle
    glass_id29 - drinking_glass
    puzzle_id33 - puzzle
    book_id45 - book
    bottle_id33 - glass_bottle
    book_id46 - book
    glass_id30 - drinking_glass
    guitar_id33 - guitar
    violin_id29 - violin
    book_id47 - book
    tv_id24 - tv
    magazine_id38 - magazine
    magazine_id39 - magazine
    glass_id31 - drinking_glass
    guitar_id34 - guitar
    glass_id32 - drinking_glass
    tv_id25 - tv
    bottle_id34 - glass_bottle
    bottle_id35 - glass_bottle
    pc_id37 - desktop
    bottle_id36 - glass_bottle
    tv_id26 - tv
    tv_id27 - tv
    pc_id38 - desktop
    bottle_id37 - glass_bottle
    magazine_id40 - magazine
    glass_id33 - drinking_glass
    violin_id30 - violin
    bottle_id38 - glass_bottle
    pc_id39 - desktop
    magazine_id41 - magazine
    guitar_id35 - guitar
    book_id48 - book
    pc_id40 - desktop
    violin_id31 - violin
    bottle_id39 - glass_bottle
    book_id49 - book
    glass_id34 - drinking_glass
    book_id50 - book
    puzzle_id34 - puzzle
    magazine_id42 - magazine
    bottle_id40 - glass_bottle
    glass_id35 - drinking_glass
    violin_id32 - violin
    magazine_id43 - magazine
    bottle_id41 - glass_bottle
    violin_id33 - violin
    tv_id28 - tv
    tv_id29 - tv
    book_id51 - book
    pc_id41 - desktop
    book_id52 - book
    magazine_id44 - magazine
    magazine_id45 - magazine
    bottle_id42 - glass_bottle
    bottle_id43 - glass_bottle
    puzzle_id35 - puzzle
    book_id53 - book
    tv_id30 - tv
    violin_id34 - violin
    bottle_id44 - glass_bottle
    puzzle_id36 - puzzle
    glass_id36 - drinking_glass
    puzzle_id37 - puzzle
    pc_id42 - desktop
    magazine_id46 - magazine
    violin_id35 - violin
    guitar_id36 - guitar
    glass_id37 - drinking_glass
    magazine_id47 - magazine
    violin_id36 - violin
    puzzle_id38 - puzzle
    guitar_id37 - guitar
    puzzle_id39 - puzzle
    book_id54 - book
    puzzle_id40 - puzzle
    magazine_id48 - magazine
    puzzle_id41 - puzzle
    glass_id38 - drinking_glass
    puzzle_id42 - puzzle
    magazine_id49 - magazine
    magazine_id50 - magazine
    bottle_id45 - glass_bottle
    book_id55 - book
    violin_id37 - violin
    puzzle_id43 - puzzle
    tv_id31 - tv
    pc_id43 - desktop
    violin_id38 - violin
    pc_id44 - desktop
    guitar_id38 - guitar
    violin_id39 - violin
    book_id56 - book
    puzzle_id44 - puzzle
    violin_id40 - violin
    guitar_id39 - guitar
    pc_id45 - desktop
    book_id57 - book
    bottle_id46 - glass_bottle
    bottle_id47 - glass_bottle
    book_id58 - book
    violin_id41 - violin
    book_id59 - book
    guitar_id40 - guitar
    tv_id32 - tv
    guitar_id41 - guitar
    magazine_id51 - magazine
    tv_id33 - tv
    violin_id42 - violin)
  (:init
    (available book_id01)
    (available book_id02)
    (available book_id03)
    (available book_id04)
    (available book_id06)
    (available book_id07)
    (available book_id08)
    (available book_id09)
    (available book_id10)
    (available book_id11)
    (available book_id12)
    (available book_id14)
    (available book_id15)
    (available book_id17)
    (available book_id18)
    (available book_id19)
    (available book_id21)
    (available book_id23)
    (available book_id24)
    (available book_id25)
    (available book_id26)
    (available book_id27)
    (available book_id28)
    (available book_id29)
    (available book_id31)
    (available book_id32)
    (available book_id33)
    (available book_id34)
    (available book_id35)
    (available book_id37)
    (available book_id39)
    (available book_id40)
    (available book_id42)
    (available book_id43)
    (available book_id44)
    (available book_id46)
    (available book_id47)
    (available book_id49)
    (available book_id50)
    (available book_id51)
    (available book_id52)
    (available book_id53)
    (available book_id54)
    (available book_id55)
    (available book_id56)
    (available book_id58)
    (available book_id59)
    (available bottle_id01)
    (available bottle_id02)
    (available bottle_id03)
    (available bottle_id06)
    (available bottle_id07)
    (available bottle_id08)
    (available bottle_id10)
    (available bottle_id11)
    (available bottle_id12)
    (available bottle_id13)
    (available bottle_id14)
    (available bottle_id15)
    (available bottle_id16)
    (available bottle_id17)
    (available bottle_id18)
    (available bottle_id19)
    (available bottle_id20)
    (available bottle_id22)
    (available bottle_id25)
    (available bottle_id26)
    (available bottle_id28)
    (available bottle_id30)
    (available bottle_id31)
    (available bottle_id32)
    (available bottle_id33)
    (available bottle_id36)
    (available bottle_id37)
    (available bottle_id38)
    (available bottle_id39)
    (available bottle_id40)
    (available bottle_id41)
    (available bottle_id42)
    (available bottle_id43)
    (available bottle_id44)
    (available bottle_id45)
    (available bottle_id46)
    (available bottle_id47)
    (available glass_id01)
    (available glass_id02)
    (available glass_id03)
    (available glass_id04)
    (available glass_id05)
    (available glass_id06)
    (available glass_id07)
    (available glass_id08)
    (available glass_id10)
    (available glass_id11)
    (available glass_id12)
    (available glass_id13)
    (available glass_id15)
    (available glass_id16)
    (available glass_id17)
    (available glass_id18)
    (available glass_id19)
    (available glass_id20)
    (available glass_id22)
    (available glass_id23)
    (available glass_id25)
    (available glass_id26)
    (available glass_id27)
    (available glass_id29)
    (available glass_id30)
    (available glass_id32)
    (available glass_id33)
    (available glass_id34)
    (available glass_id35)
    (available glass_id36)
    (available glass_id38)
    (available guitar_id01)
    (available guitar_id02)
    (available guitar_id03)
    (available guitar_id04)
    (available guitar_id05)
    (available guitar_id06)
    (available guitar_id08)
    (available guitar_id09)
    (available guitar_id10)
    (available guitar_id12)
    (available guitar_id13)
    (available guitar_id14)
    (available guitar_id15)
    (available guitar_id16)
    (available guitar_id17)
    (available guitar_id18)
    (available guitar_id19)
    (available guitar_id20)
    (available guitar_id21)
    (available guitar_id22)
    (available guitar_id23)
    (available guitar_id24)
    (available guitar_id25)
    (available guitar_id26)
    (available guitar_id27)
    (available guitar_id28)
    (available guitar_id29)
    (available guitar_id31)
    (available guitar_id33)
    (available guitar_id36)
    (available guitar_id38)
    (available guitar_id39)
    (available guitar_id40)
    (available guitar_id41)
    (available magazine_id01)
    (available magazine_id03)
    (available magazine_id04)
    (available magazine_id08)
    (available magazine_id09)
    (available magazine_id13)
    (available magazine_id14)
    (available magazine_id15)
    (available magazine_id16)
    (available magazine_id17)
    (available magazine_id19)
    (available magazine_id20)
    (available magazine_id21)
    (available magazine_id23)
    (available magazine_id24)
    (available magazine_id25)
    (available magazine_id26)
    (available magazine_id27)
    (available magazine_id28)
    (available magazine_id31)
    (available magazine_id32)
    (available magazine_id35)
    (available magazine_id37)
    (available magazine_id38)
    (available magazine_id40)
    (available magazine_id41)
    (available magazine_id43)
    (available magazine_id44)
    (available magazine_id45)
    (available magazine_id46)
    (available magazine_id47)
    (available magazine_id49)
    (available magazine_id50)
    (available magazine_id51)
    (available pc_id01)
    (available pc_id02)
    (available pc_id04)
    (available pc_id05)
    (available pc_id06)
    (available pc_id07)
    (available pc_id08)
    (available pc_id09)
    (available pc_id12)
    (available pc_id13)
    (available pc_id14)
    (available pc_id15)
    (available pc_id16)
    (available pc_id17)
    (available pc_id18)
    (available pc_id19)
    (available pc_id20)
    (available pc_id21)
    (available pc_id22)
    (available pc_id23)
    (available pc_id25)
    (available pc_id26)
    (available pc_id27)
    (available pc_id28)
    (available pc_id29)
    (available pc_id31)
    (available pc_id32)
    (available pc_id35)
    (available pc_id37)
    (available pc_id38)
    (available pc_id40)
    (available pc_id41)
    (available pc_id43)
    (available pc_id44)
    (available pc_id45)
    (available puzzle_id01)
    (available puzzle_id02)
    (available puzzle_id04)
    (available puzzle_id05)
    (available puzzle_id06)
    (available puzzle_id07)
    (available puzzle_id09)
    (available puzzle_id10)
    (available puzzle_id11)
    (available puzzle_id12)
    (available puzzle_id15)
    (available puzzle_id16)
    (available puzzle_id17)
    (available puzzle_id18)
    (available puzzle_id19)
    (available puzzle_id20)
    (available puzzle_id21)
    (available puzzle_id22)
    (available puzzle_id24)
    (available puzzle_id25)
    (available puzzle_id26)
    (available puzzle_id27)
    (available puzzle_id28)
    (available puzzle_id29)
    (available puzzle_id30)
    (available puzzle_id32)
    (available puzzle_id33)
    (available puzzle_id34)
    (available puzzle_id36)
    (available puzzle_id37)
    (available puzzle_id38)
    (available puzzle_id40)
    (available puzzle_id41)
    (available puzzle_id44)
    (available tv_id01)
    (available tv_id02)
    (available tv_id03)
    (available tv_id05)
    (available tv_id08)
    (available tv_id09)
    (available tv_id10)
    (available tv_id12)
    (available tv_id13)
    (available tv_id15)
    (available tv_id16)
    (available tv_id17)
    (available tv_id18)
    (available tv_id19)
    (available tv_id20)
    (available tv_id21)
    (available tv_id22)
    (available tv_id23)
    (available tv_id24)
    (available tv_id25)
    (available tv_id26)
    (available tv_id28)
    (available tv_id29)
    (available tv_id30)
    (available tv_id31)
    (available tv_id32)
    (available violin_id01)
    (available violin_id02)
    (available violin_id03)
    (available violin_id04)
    (available violin_id05)
    (available violin_id06)
    (available violin_id07)
    (available violin_id08)
    (available violin_id10)
    (available violin_id11)
    (available violin_id12)
    (available violin_id13)
    (available violin_id14)
    (available violin_id15)
    (available violin_id16)
    (available violin_id18)
    (available violin_id19)
    (available violin_id21)
    (available violin_id23)
    (available violin_id25)
    (available violin_id26)
    (available violin_id27)
    (available violin_id28)
    (available violin_id29)
    (available violin_id30)
    (available violin_id31)
    (available violin_id32)
    (available violin_id34)
    (available violin_id35)
    (available violin_id37)
    (available violin_id38)
    (available violin_id39)
    (available violin_id40)
    (available violin_id41)
    (be book_id01 library1)
    (be book_id02 library1)
    (be book_id03 library1)
    (be book_id04 library1)
    (be book_id05 library1)
    (be book_id06 library1)
    (be book_id07 library1)
    (be book_id08 library1)
    (be book_id09 library1)
    (be book_id10 library1)
    (be book_id11 library1)
    (be book_id12 library1)
    (be book_id13 library1)
    (be book_id14 library1)
    (be book_id15 library1)
    (be book_id16 library1)
    (be book_id17 library1)
    (be book_id18 library1)
    (be book_id19 library1)
    (be book_id20 library1)
    (be book_id21 library1)
    (be book_id22 library1)
    (be book_id23 library1)
    (be book_id24 library1)
    (be book_id25 library1)
    (be book_id26 library1)
    (be book_id27 library1)
    (be book_id28 library1)
    (be book_id29 library1)
    (be book_id30 library1)
    (be book_id31 library1)
    (be book_id32 library1)
    (be book_id33 library1)
    (be book_id34 library1)
    (be book_id35 library1)
    (be book_id36 library1)
    (be book_id37 library1)
    (be book_id38 library1)
    (be book_id39 library1)
    (be book_id40 library1)
    (be book_id41 library1)
    (be book_id42 library1)
    (be book_id43 library1)
    (be book_id44 library1)
    (be book_id45 library1)
    (be book_id46 library1)
    (be book_id47 library1)
    (be book_id48 library1)
    (be book_id49 library1)
    (be book_id50 library1)
    (be book_id51 library1)
    (be book_id52 library1)
    (be book_id53 library1)
    (be book_id54 library1)
    (be book_id55 library1)
    (be book_id56 library1)
    (be book_id57 library1)
    (be book_id58 library1)
    (be book_id59 library1)
    (be bottle_id01 kitchen1)
    (be bottle_id02 kitchen1)
    (be bottle_id03 kitchen1)
    (be bottle_id04 kitchen1)
    (be bottle_id05 kitchen1)
    (be bottle_id06 kitchen1)
    (be bottle_id07 kitchen1)
    (be bottle_id08 kitchen1)
    (be bottle_id09 kitchen1)
    (be bottle_id10 kitchen1)
    (be bottle_id11 kitchen1)
    (be bottle_id12 kitchen1)
    (be bottle_id13 kitchen1)
    (be bottle_id14 kitchen1)
    (be bottle_id15 kitchen1)
    (be bottle_id16 kitchen1)
    (be bottle_id17 kitchen1)
    (be bottle_id18 kitchen1)
    (be bottle_id19 kitchen1)
    (be bottle_id20 kitchen1)
    (be bottle_id21 kitchen1)
    (be bottle_id22 kitchen1)
    (be bottle_id23 kitchen1)
    (be bottle_id24 kitchen1)
    (be bottle_id25 kitchen1)
    (be bottle_id26 kitchen1)
    (be bottle_id27 kitchen1)
    (be bottle_id28 kitchen1)
    (be bottle_id29 kitchen1)
    (be bottle_id30 kitchen1)
    (be bottle_id31 kitchen1)
    (be bottle_id32 kitchen1)
    (be bottle_id33 kitchen1)
    (be bottle_id34 kitchen1)
    (be bottle_id35 kitchen1)
    (be bottle_id36 kitchen1)
    (be bottle_id37 kitchen1)
    (be bottle_id38 kitchen1)
    (be bottle_id39 kitchen1)
    (be bottle_id40 kitchen1)
    (be bottle_id41 kitchen1)
    (be bottle_id42 kitchen1)
    (be bottle_id43 kitchen1)
    (be bottle_id44 kitchen1)
    (be bottle_id45 kitchen1)
    (be bottle_id46 kitchen1)
    (be bottle_id47 kitchen1)
    (be glass_id01 kitchen1)
    (be glass_id02 kitchen1)
    (be glass_id03 kitchen1)
    (be glass_id04 kitchen1)
    (be glass_id05 kitchen1)
    (be glass_id06 kitchen1)
    (be glass_id07 kitchen1)
    (be glass_id08 kitchen1)
    (be glass_id09 kitchen1)
    (be glass_id10 kitchen1)
    (be glass_id11 kitchen1)
    (be glass_id12 kitchen1)
    (be glass_id13 kitchen1)
    (be glass_id14 kitchen1)
    (be glass_id15 kitchen1)
    (be glass_id16 kitchen1)
    (be glass_id17 kitchen1)
    (be glass_id18 kitchen1)
    (be glass_id19 kitchen1)
    (be glass_id20 kitchen1)
    (be glass_id21 kitchen1)
    (be glass_id22 kitchen1)
    (be glass_id23 kitchen1)
    (be glass_id24 kitchen1)
    (be glass_id25 kitchen1)
    (be glass_id26 kitchen1)
    (be glass_id27 kitchen1)
    (be glass_id28 kitchen1)
    (be glass_id29 kitchen1)
    (be glass_id30 kitchen1)
    (be glass_id31 kitchen1)
    (be glass_id32 kitchen1)
    (be glass_id33 kitchen1)
    (be glass_id34 kitchen1)
    (be glass_id35 kitchen1)
    (be glass_id36 kitchen1)
    (be glass_id37 kitchen1)
    (be glass_id38 kitchen1)
    (be guitar_id01 music_room1)
    (be guitar_id02 music_room1)
    (be guitar_id03 music_room1)
    (be guitar_id04 music_room1)
    (be guitar_id05 music_room1)
    (be guitar_id06 music_room1)
    (be guitar_id07 music_room1)
    (be guitar_id08 music_room1)
    (be guitar_id09 music_room1)
    (be guitar_id10 music_room1)
    (be guitar_id11 music_room1)
    (be guitar_id12 music_room1)
    (be guitar_id13 music_room1)
    (be guitar_id14 music_room1)
    (be guitar_id15 music_room1)
    (be guitar_id16 music_room1)
    (be guitar_id17 music_room1)
    (be guitar_id18 music_room1)
    (be guitar_id19 music_room1)
    (be guitar_id20 music_room1)
    (be guitar_id21 music_room1)
    (be guitar_id22 music_room1)
    (be guitar_id23 music_room1)
    (be guitar_id24 music_room1)
    (be guitar_id25 music_room1)
    (be guitar_id26 music_room1)
    (be guitar_id27 music_room1)
    (be guitar_id28 music_room1)
    (be guitar_id29 music_room1)
    (be guitar_id30 music_room1)
    (be guitar_id31 music_room1)
    (be guitar_id32 music_room1)
    (be guitar_id33 music_room1)
    (be guitar_id34 music_room1)
    (be guitar_id35 music_room1)
    (be guitar_id36 music_room1)
    (be guitar_id37 music_room1)
    (be guitar_id38 music_room1)
    (be guitar_id39 music_room1)
    (be guitar_id40 music_room1)
    (be guitar_id41 music_room1)
    (be magazine_id01 library1)
    (be magazine_id02 library1)
    (be magazine_id03 library1)
    (be magazine_id04 library1)
    (be magazine_id05 library1)
    (be magazine_id06 library1)
    (be magazine_id07 library1)
    (be magazine_id08 library1)
    (be magazine_id09 library1)
    (be magazine_id10 library1)
    (be magazine_id11 library1)
    (be magazine_id12 library1)
    (be magazine_id13 library1)
    (be magazine_id14 library1)
    (be magazine_id15 library1)
    (be magazine_id16 library1)
    (be magazine_id17 library1)
    (be magazine_id18 library1)
    (be magazine_id19 library1)
    (be magazine_id20 library1)
    (be magazine_id21 library1)
    (be magazine_id22 library1)
    (be magazine_id23 library1)
    (be magazine_id24 library1)
    (be magazine_id25 library1)
    (be magazine_id26 library1)
    (be magazine_id27 library1)
    (be magazine_id28 library1)
    (be magazine_id29 library1)
    (be magazine_id30 library1)
    (be magazine_id31 library1)
    (be magazine_id32 library1)
    (be magazine_id33 library1)
    (be magazine_id34 library1)
    (be magazine_id35 library1)
    (be magazine_id36 library1)
    (be magazine_id37 library1)
    (be magazine_id38 library1)
    (be magazine_id39 library1)
    (be magazine_id40 library1)
    (be magazine_id41 library1)
    (be magazine_id42 library1)
    (be magazine_id43 library1)
    (be magazine_id44 library1)
    (be magazine_id45 library1)
    (be magazine_id46 library1)
    (be magazine_id47 library1)
    (be magazine_id48 library1)
    (be magazine_id49 library1)
    (be magazine_id50 library1)
    (be magazine_id51 library1)
    (be pc_id01 library1)
    (be pc_id02 library1)
    (be pc_id03 library1)
    (be pc_id04 library1)
    (be pc_id05 library1)
    (be pc_id06 library1)
    (be pc_id07 library1)
    (be pc_id08 library1)
    (be pc_id09 library1)
    (be pc_id10 library1)
    (be pc_id11 library1)
    (be pc_id12 library1)
    (be pc_id13 library1)
    (be pc_id14 library1)
    (be pc_id15 library1)
    (be pc_id16 library1)
    (be pc_id17 library1)
    (be pc_id18 library1)
    (be pc_id19 library1)
    (be pc_id20 library1)
    (be pc_id21 library1)
    (be pc_id22 library1)
    (be pc_id23 library1)
    (be pc_id24 library1)
    (be pc_id25 library1)
    (be pc_id26 library1)
    (be pc_id27 library1)
    (be pc_id28 library1)
    (be pc_id29 library1)
    (be pc_id30 library1)
    (be pc_id31 library1)
    (be pc_id32 library1)
    (be pc_id33 library1)
    (be pc_id34 library1)
    (be pc_id35 library1)
    (be pc_id36 library1)
    (be pc_id37 library1)
    (be pc_id38 library1)
    (be pc_id39 library1)
    (be pc_id40 library1)
    (be pc_id41 library1)
    (be pc_id42 library1)
    (be pc_id43 library1)
    (be pc_id44 library1)
    (be pc_id45 library1)
    (be puzzle_id01 library1)
    (be puzzle_id02 library1)
    (be puzzle_id03 library1)
    (be puzzle_id04 library1)
    (be puzzle_id05 library1)
    (be puzzle_id06 library1)
    (be puzzle_id07 library1)
    (be puzzle_id08 library1)
    (be puzzle_id09 library1)
    (be puzzle_id10 library1)
    (be puzzle_id11 library1)
    (be puzzle_id12 library1)
    (be puzzle_id13 library1)
    (be puzzle_id14 library1)
    (be puzzle_id15 library1)
    (be puzzle_id16 library1)
    (be puzzle_id17 library1)
    (be puzzle_id18 library1)
    (be puzzle_id19 library1)
    (be puzzle_id20 library1)
    (be puzzle_id21 library1)
    (be puzzle_id22 library1)
    (be puzzle_id23 library1)
    (be puzzle_id24 library1)
    (be puzzle_id25 library1)
    (be puzzle_id26 library1)
    (be puzzle_id27 library1)
    (be puzzle_id28 library1)
    (be puzzle_id29 library1)
    (be puzzle_id30 library1)
    (be puzzle_id31 library1)
    (be puzzle_id32 library1)
    (be puzzle_id33 library1)
    (be puzzle_id34 library1)
    (be puzzle_id35 library1)
    (be puzzle_id36 library1)
    (be puzzle_id37 library1)
    (be puzzle_id38 library1)
    (be puzzle_id39 library1)
    (be puzzle_id40 library1)
    (be puzzle_id41 library1)
    (be puzzle_id42 library1)
    (be puzzle_id43 library1)
    (be puzzle_id44 library1)
    (be robot1 bedroom29)
    (be robot2 bedroom5)
    (be robot3 bedroom17)
    (be robot4 bedroom12)
    (be senior1 sunroom13)
    (be senior10 bedroom14)
    (be senior11 bedroom20)
    (be senior12 bedroom16)
    (be senior13 bedroom30)
    (be senior14 bedroom20)
    (be senior15 sunroom9)
    (be senior16 bedroom16)
    (be senior17 bedroom6)
    (be senior18 bedroom6)
    (be senior19 bedroom16)
    (be senior2 bedroom6)
    (be senior20 bedroom20)
    (be senior21 bedroom30)
    (be senior22 bedroom8)
    (be senior23 bedroom14)
    (be senior24 sunroom8)
    (be senior25 bedroom6)
    (be senior26 bedroom1)
    (be senior27 bedroom23)
    (be senior28 bedroom20)
    (be senior29 bedroom16)
    (be senior3 bedroom9)
    (be senior30 bedroom19)
    (be senior31 bedroom1)
    (be senior32 bedroom12)
    (be senior33 sunroom11)
    (be senior34 bedroom2)
    (be senior35 bedroom23)
    (be senior36 sunroom3)
    (be senior37 bedroom1)
    (be senior38 bedroom5)
    (be senior39 sunroom12)
    (be senior4 bedroom18)
    (be senior40 sunroom10)
    (be senior5 bedroom31)
    (be senior6 sunroom9)
    (be senior7 bedroom17)
    (be senior8 bedroom11)
    (be senior9 bedroom8)
    (be tv_id01 library1)
    (be tv_id02 library1)
    (be tv_id03 library1)
    (be tv_id04 library1)
    (be tv_id05 library1)
    (be tv_id06 library1)
    (be tv_id07 library1)
    (be tv_id08 library1)
    (be tv_id09 library1)
    (be tv_id10 library1)
    (be tv_id11 library1)
    (be tv_id12 library1)
    (be tv_id13 library1)
    (be tv_id14 library1)
    (be tv_id15 library1)
    (be tv_id16 library1)
    (be tv_id17 library1)
    (be tv_id18 library1)
    (be tv_id19 library1)
    (be tv_id20 library1)
    (be tv_id21 library1)
    (be tv_id22 library1)
    (be tv_id23 library1)
    (be tv_id24 library1)
    (be tv_id25 library1)
    (be tv_id26 library1)
    (be tv_id27 library1)
    (be tv_id28 library1)
    (be tv_id29 library1)
    (be tv_id30 library1)
    (be tv_id31 library1)
    (be tv_id32 library1)
    (be tv_id33 library1)
    (be violin_id01 music_room1)
    (be violin_id02 music_room1)
    (be violin_id03 music_room1)
    (be violin_id04 music_room1)
    (be violin_id05 music_room1)
    (be violin_id06 music_room1)
    (be violin_id07 music_room1)
    (be violin_id08 music_room1)
    (be violin_id09 music_room1)
    (be violin_id10 music_room1)
    (be violin_id11 music_room1)
    (be violin_id12 music_room1)
    (be violin_id13 music_room1)
    (be violin_id14 music_room1)
    (be violin_id15 music_room1)
    (be violin_id16 music_room1)
    (be violin_id17 music_room1)
    (be violin_id18 music_room1)
    (be violin_id19 music_room1)
    (be violin_id20 music_room1)
    (be violin_id21 music_room1)
    (be violin_id22 music_room1)
    (be violin_id23 music_room1)
    (be violin_id24 music_room1)
    (be violin_id25 music_room1)
    (be violin_id26 music_room1)
    (be violin_id27 music_room1)
    (be violin_id28 music_room1)
    (be violin_id29 music_room1)
    (be violin_id30 music_room1)
    (be violin_id31 music_room1)
    (be violin_id32 music_room1)
    (be violin_id33 music_room1)
    (be violin_id34 music_room1)
    (be violin_id35 music_room1)
    (be violin_id36 music_room1)
    (be violin_id37 music_room1)
    (be violin_id38 music_room1)
    (be violin_id39 music_room1)
    (be violin_id40 music_room1)
    (be violin_id41 music_room1)
    (be violin_id42 music_room1)
    (cheerful senior32)
    (cheerful senior38)
    (cheerful senior7)
    (comfort_time senior20)
    (comfort_time senior7)
    (entertained senior20)
    (entertained senior9)
    (hydration_time senior24)
    (iot_tagged book_id01)
    (iot_tagged book_id02)
    (iot_tagged book_id04)
    (iot_tagged book_id06)
    (iot_tagged book_id10)
    (iot_tagged book_id11)
    (iot_tagged book_id12)
    (iot_tagged book_id14)
    (iot_tagged book_id16)
    (iot_tagged book_id18)
    (iot_tagged book_id21)
    (iot_tagged book_id25)
    (iot_tagged book_id26)
    (iot_tagged book_id27)
    (iot_tagged book_id32)
    (iot_tagged book_id36)
    (iot_tagged book_id37)
    (iot_tagged book_id40)
    (iot_tagged book_id41)
    (iot_tagged book_id44)
    (iot_tagged book_id45)
    (iot_tagged book_id47)
    (iot_tagged book_id49)
    (iot_tagged book_id51)
    (iot_tagged book_id52)
    (iot_tagged book_id53)
    (iot_tagged book_id54)
    (iot_tagged book_id55)
    (iot_tagged book_id56)
    (iot_tagged book_id57)
    (iot_tagged book_id58)
    (iot_tagged bottle_id01)
    (iot_tagged bottle_id02)
    (iot_tagged bottle_id04)
    (iot_tagged bottle_id07)
    (iot_tagged bottle_id08)
    (iot_tagged bottle_id11)
    (iot_tagged bottle_id12)
    (iot_tagged bottle_id13)
    (iot_tagged bottle_id14)
    (iot_tagged bottle_id15)
    (iot_tagged bottle_id16)
    (iot_tagged bottle_id17)
    (iot_tagged bottle_id22)
    (iot_tagged bottle_id23)
    (iot_tagged bottle_id25)
    (iot_tagged bottle_id26)
    (iot_tagged bottle_id27)
    (iot_tagged bottle_id28)
    (iot_tagged bottle_id30)
    (iot_tagged bottle_id32)
    (iot_tagged bottle_id36)
    (iot_tagged bottle_id38)
    (iot_tagged bottle_id41)
    (iot_tagged bottle_id43)
    (iot_tagged bottle_id45)
    (iot_tagged bottle_id46)
    (iot_tagged bottle_id47)
    (iot_tagged glass_id01)
    (iot_tagged glass_id02)
    (iot_tagged glass_id03)
    (iot_tagged glass_id04)
    (iot_tagged glass_id05)
    (iot_tagged glass_id08)
    (iot_tagged glass_id10)
    (iot_tagged glass_id11)
    (iot_tagged glass_id12)
    (iot_tagged glass_id13)
    (iot_tagged glass_id16)
    (iot_tagged glass_id18)
    (iot_tagged glass_id19)
    (iot_tagged glass_id21)
    (iot_tagged glass_id22)
    (iot_tagged glass_id24)
    (iot_tagged glass_id27)
    (iot_tagged glass_id28)
    (iot_tagged glass_id29)
    (iot_tagged glass_id33)
    (iot_tagged glass_id34)
    (iot_tagged glass_id36)
    (iot_tagged glass_id38)
    (iot_tagged guitar_id02)
    (iot_tagged guitar_id11)
    (iot_tagged guitar_id15)
    (iot_tagged guitar_id19)
    (iot_tagged guitar_id20)
    (iot_tagged guitar_id22)
    (iot_tagged guitar_id28)
    (iot_tagged guitar_id31)
    (iot_tagged guitar_id33)
    (iot_tagged guitar_id38)
    (iot_tagged guitar_id39)
    (iot_tagged magazine_id02)
    (iot_tagged magazine_id03)
    (iot_tagged magazine_id04)
    (iot_tagged magazine_id05)
    (iot_tagged magazine_id07)
    (iot_tagged magazine_id08)
    (iot_tagged magazine_id09)
    (iot_tagged magazine_id10)
    (iot_tagged magazine_id11)
    (iot_tagged magazine_id12)
    (iot_tagged magazine_id14)
    (iot_tagged magazine_id15)
    (iot_tagged magazine_id18)
    (iot_tagged magazine_id19)
    (iot_tagged magazine_id23)
    (iot_tagged magazine_id24)
    (iot_tagged magazine_id27)
    (iot_tagged magazine_id28)
    (iot_tagged magazine_id29)
    (iot_tagged magazine_id30)
    (iot_tagged magazine_id31)
    (iot_tagged magazine_id32)
    (iot_tagged magazine_id34)
    (iot_tagged magazine_id36)
    (iot_tagged magazine_id37)
    (iot_tagged magazine_id41)
    (iot_tagged magazine_id44)
    (iot_tagged magazine_id45)
    (iot_tagged magazine_id47)
    (iot_tagged magazine_id49)
    (iot_tagged pc_id01)
    (iot_tagged pc_id02)
    (iot_tagged pc_id03)
    (iot_tagged pc_id04)
    (iot_tagged pc_id05)
    (iot_tagged pc_id07)
    (iot_tagged pc_id10)
    (iot_tagged pc_id12)
    (iot_tagged pc_id14)
    (iot_tagged pc_id16)
    (iot_tagged pc_id21)
    (iot_tagged pc_id22)
    (iot_tagged pc_id25)
    (iot_tagged pc_id31)
    (iot_tagged pc_id32)
    (iot_tagged pc_id33)
    (iot_tagged pc_id34)
    (iot_tagged pc_id35)
    (iot_tagged pc_id38)
    (iot_tagged pc_id39)
    (iot_tagged pc_id41)
    (iot_tagged pc_id42)
    (iot_tagged pc_id43)
    (iot_tagged puzzle_id01)
    (iot_tagged puzzle_id02)
    (iot_tagged puzzle_id03)
    (iot_tagged puzzle_id05)
    (iot_tagged puzzle_id06)
    (iot_tagged puzzle_id07)
    (iot_tagged puzzle_id08)
    (iot_tagged puzzle_id09)
    (iot_tagged puzzle_id10)
    (iot_tagged puzzle_id12)
    (iot_tagged puzzle_id14)
    (iot_tagged puzzle_id15)
    (iot_tagged puzzle_id17)
    (iot_tagged puzzle_id19)
    (iot_tagged puzzle_id20)
    (iot_tagged puzzle_id23)
    (iot_tagged puzzle_id24)
    (iot_tagged puzzle_id25)
    (iot_tagged puzzle_id26)
    (iot_tagged puzzle_id27)
    (iot_tagged puzzle_id28)
    (iot_tagged puzzle_id29)
    (iot_tagged puzzle_id30)
    (iot_tagged puzzle_id31)
    (iot_tagged puzzle_id33)
    (iot_tagged puzzle_id36)
    (iot_tagged puzzle_id40)
    (iot_tagged puzzle_id41)
    (iot_tagged puzzle_id42)
    (iot_tagged puzzle_id44)
    (iot_tagged tv_id01)
    (iot_tagged tv_id03)
    (iot_tagged tv_id08)
    (iot_tagged tv_id10)
    (iot_tagged tv_id14)
    (iot_tagged tv_id15)
    (iot_tagged tv_id19)
    (iot_tagged tv_id20)
    (iot_tagged tv_id26)
    (iot_tagged tv_id27)
    (iot_tagged tv_id32)
    (iot_tagged violin_id01)
    (iot_tagged violin_id04)
    (iot_tagged violin_id05)
    (iot_tagged violin_id08)
    (iot_tagged violin_id12)
    (iot_tagged violin_id13)
    (iot_tagged violin_id15)
    (iot_tagged violin_id16)
    (iot_tagged violin_id19)
    (iot_tagged violin_id22)
    (iot_tagged violin_id24)
    (iot_tagged violin_id25)
    (iot_tagged violin_id27)
    (iot_tagged violin_id31)
    (iot_tagged violin_id34)
    (iot_tagged violin_id37)
    (iot_tagged violin_id39)
    (iot_tagged violin_id40)
    (iot_tagged violin_id41)
    (iot_tagged violin_id42)
    (path bedroom1 corridor10)
    (path bedroom10 corridor6)
    (path bedroom11 corridor9)
    (path bedroom12 corridor2)
    (path bedroom13 corridor4)
    (path bedroom14 corridor5)
    (path bedroom15 corridor9)
    (path bedroom16 corridor5)
    (path bedroom17 corridor11)
    (path bedroom18 corridor2)
    (path bedroom19 corridor3)
    (path bedroom2 corridor12)
    (path bedroom20 corridor6)
    (path bedroom21 corridor11)
    (path bedroom22 corridor12)
    (path bedroom23 corridor7)
    (path bedroom24 corridor1)
    (path bedroom25 corridor5)
    (path bedroom26 corridor7)
    (path bedroom27 corridor5)
    (path bedroom28 corridor7)
    (path bedroom29 corridor6)
    (path bedroom3 corridor5)
    (path bedroom30 corridor7)
    (path bedroom31 corridor4)
    (path bedroom32 corridor5)
    (path bedroom33 corridor7)
    (path bedroom4 corridor2)
    (path bedroom5 corridor4)
    (path bedroom6 corridor11)
    (path bedroom7 corridor9)
    (path bedroom8 corridor12)
    (path bedroom9 corridor4)
    (path corridor1 bedroom24)
    (path corridor1 corridor2)
    (path corridor1 corridor6)
    (path corridor1 corridor9)
    (path corridor1 sunroom6)
    (path corridor1 sunroom7)
    (path corridor10 bedroom1)
    (path corridor10 corridor11)
    (path corridor10 corridor13)
    (path corridor10 corridor2)
    (path corridor10 sunroom12)
    (path corridor10 sunroom4)
    (path corridor11 bedroom17)
    (path corridor11 bedroom21)
    (path corridor11 bedroom6)
    (path corridor11 corridor10)
    (path corridor11 corridor12)
    (path corridor12 bedroom2)
    (path corridor12 bedroom22)
    (path corridor12 bedroom8)
    (path corridor12 corridor11)
    (path corridor13 corridor10)
    (path corridor13 dinning_room1)
    (path corridor13 library1)
    (path corridor13 sunroom5)
    (path corridor2 bedroom12)
    (path corridor2 bedroom18)
    (path corridor2 bedroom4)
    (path corridor2 corridor1)
    (path corridor2 corridor10)
    (path corridor2 corridor3)
    (path corridor2 corridor7)
    (path corridor2 corridor8)
    (path corridor3 bedroom19)
    (path corridor3 corridor2)
    (path corridor3 corridor4)
    (path corridor3 corridor5)
    (path corridor4 bedroom13)
    (path corridor4 bedroom31)
    (path corridor4 bedroom5)
    (path corridor4 bedroom9)
    (path corridor4 corridor3)
    (path corridor5 bedroom14)
    (path corridor5 bedroom16)
    (path corridor5 bedroom25)
    (path corridor5 bedroom27)
    (path corridor5 bedroom3)
    (path corridor5 bedroom32)
    (path corridor5 corridor3)
    (path corridor5 sunroom10)
    (path corridor5 sunroom13)
    (path corridor6 bedroom10)
    (path corridor6 bedroom20)
    (path corridor6 bedroom29)
    (path corridor6 corridor1)
    (path corridor7 bedroom23)
    (path corridor7 bedroom26)
    (path corridor7 bedroom28)
    (path corridor7 bedroom30)
    (path corridor7 bedroom33)
    (path corridor7 corridor2)
    (path corridor7 music_room1)
    (path corridor7 sunroom8)
    (path corridor7 sunroom9)
    (path corridor8 corridor2)
    (path corridor8 sunroom1)
    (path corridor8 sunroom2)
    (path corridor9 bedroom11)
    (path corridor9 bedroom15)
    (path corridor9 bedroom7)
    (path corridor9 corridor1)
    (path corridor9 sunroom11)
    (path corridor9 sunroom3)
    (path dinning_room1 corridor13)
    (path dinning_room1 kitchen1)
    (path kitchen1 dinning_room1)
    (path library1 corridor13)
    (path music_room1 corridor7)
    (path sunroom1 corridor8)
    (path sunroom10 corridor5)
    (path sunroom11 corridor9)
    (path sunroom12 corridor10)
    (path sunroom13 corridor5)
    (path sunroom2 corridor8)
    (path sunroom3 corridor9)
    (path sunroom4 corridor10)
    (path sunroom5 corridor13)
    (path sunroom6 corridor1)
    (path sunroom7 corridor1)
    (path sunroom8 corridor7)
    (path sunroom9 corridor7)
    (terrified senior24)
    (= (handling_time) 10)
    (= (moving_time bedroom1 corridor10) 35)
    (= (moving_time bedroom10 corridor6) 45)
    (= (moving_time bedroom11 corridor9) 40)
    (= (moving_time bedroom12 corridor2) 20)
    (= (moving_time bedroom13 corridor4) 40)
    (= (moving_time bedroom14 corridor5) 35)
    (= (moving_time bedroom15 corridor9) 40)
    (= (moving_time bedroom16 corridor5) 25)
    (= (moving_time bedroom17 corridor11) 45)
    (= (moving_time bedroom18 corridor2) 45)
    (= (moving_time bedroom19 corridor3) 25)
    (= (moving_time bedroom2 corridor12) 40)
    (= (moving_time bedroom20 corridor6) 20)
    (= (moving_time bedroom21 corridor11) 45)
    (= (moving_time bedroom22 corridor12) 20)
    (= (moving_time bedroom23 corridor7) 40)
    (= (moving_time bedroom24 corridor1) 50)
    (= (moving_time bedroom25 corridor5) 20)
    (= (moving_time bedroom26 corridor7) 40)
    (= (moving_time bedroom27 corridor5) 30)
    (= (moving_time bedroom28 corridor7) 40)
    (= (moving_time bedroom29 corridor6) 20)
    (= (moving_time bedroom3 corridor5) 20)
    (= (moving_time bedroom30 corridor7) 35)
    (= (moving_time bedroom31 corridor4) 20)
    (= (moving_time bedroom32 corridor5) 45)
    (= (moving_time bedroom33 corridor7) 20)
    (= (moving_time bedroom4 corridor2) 35)
    (= (moving_time bedroom5 corridor4) 20)
    (= (moving_time bedroom6 corridor11) 35)
    (= (moving_time bedroom7 corridor9) 40)
    (= (moving_time bedroom8 corridor12) 45)
    (= (moving_time bedroom9 corridor4) 50)
    (= (moving_time corridor1 bedroom24) 50)
    (= (moving_time corridor1 corridor2) 60)
    (= (moving_time corridor1 corridor6) 45)
    (= (moving_time corridor1 corridor9) 30)
    (= (moving_time corridor1 sunroom6) 50)
    (= (moving_time corridor1 sunroom7) 30)
    (= (moving_time corridor10 bedroom1) 35)
    (= (moving_time corridor10 corridor11) 50)
    (= (moving_time corridor10 corridor13) 55)
    (= (moving_time corridor10 corridor2) 35)
    (= (moving_time corridor10 sunroom12) 25)
    (= (moving_time corridor10 sunroom4) 45)
    (= (moving_time corridor11 bedroom17) 45)
    (= (moving_time corridor11 bedroom21) 45)
    (= (moving_time corridor11 bedroom6) 35)
    (= (moving_time corridor11 corridor10) 50)
    (= (moving_time corridor11 corridor12) 30)
    (= (moving_time corridor12 bedroom2) 40)
    (= (moving_time corridor12 bedroom22) 20)
    (= (moving_time corridor12 bedroom8) 45)
    (= (moving_time corridor12 corridor11) 30)
    (= (moving_time corridor13 corridor10) 55)
    (= (moving_time corridor13 dinning_room1) 35)
    (= (moving_time corridor13 library1) 40)
    (= (moving_time corridor13 sunroom5) 50)
    (= (moving_time corridor2 bedroom12) 20)
    (= (moving_time corridor2 bedroom18) 45)
    (= (moving_time corridor2 bedroom4) 35)
    (= (moving_time corridor2 corridor1) 60)
    (= (moving_time corridor2 corridor10) 35)
    (= (moving_time corridor2 corridor3) 35)
    (= (moving_time corridor2 corridor7) 30)
    (= (moving_time corridor2 corridor8) 30)
    (= (moving_time corridor3 bedroom19) 25)
    (= (moving_time corridor3 corridor2) 35)
    (= (moving_time corridor3 corridor4) 45)
    (= (moving_time corridor3 corridor5) 55)
    (= (moving_time corridor4 bedroom13) 40)
    (= (moving_time corridor4 bedroom31) 20)
    (= (moving_time corridor4 bedroom5) 20)
    (= (moving_time corridor4 bedroom9) 50)
    (= (moving_time corridor4 corridor3) 45)
    (= (moving_time corridor5 bedroom14) 35)
    (= (moving_time corridor5 bedroom16) 25)
    (= (moving_time corridor5 bedroom25) 20)
    (= (moving_time corridor5 bedroom27) 30)
    (= (moving_time corridor5 bedroom3) 20)
    (= (moving_time corridor5 bedroom32) 45)
    (= (moving_time corridor5 corridor3) 55)
    (= (moving_time corridor5 sunroom10) 35)
    (= (moving_time corridor5 sunroom13) 20)
    (= (moving_time corridor6 bedroom10) 45)
    (= (moving_time corridor6 bedroom20) 20)
    (= (moving_time corridor6 bedroom29) 20)
    (= (moving_time corridor6 corridor1) 45)
    (= (moving_time corridor7 bedroom23) 40)
    (= (moving_time corridor7 bedroom26) 40)
    (= (moving_time corridor7 bedroom28) 40)
    (= (moving_time corridor7 bedroom30) 35)
    (= (moving_time corridor7 bedroom33) 20)
    (= (moving_time corridor7 corridor2) 30)
    (= (moving_time corridor7 music_room1) 25)
    (= (moving_time corridor7 sunroom8) 25)
    (= (moving_time corridor7 sunroom9) 35)
    (= (moving_time corridor8 corridor2) 30)
    (= (moving_time corridor8 sunroom1) 40)
    (= (moving_time corridor8 sunroom2) 40)
    (= (moving_time corridor9 bedroom11) 40)
    (= (moving_time corridor9 bedroom15) 40)
    (= (moving_time corridor9 bedroom7) 40)
    (= (moving_time corridor9 corridor1) 30)
    (= (moving_time corridor9 sunroom11) 45)
    (= (moving_time corridor9 sunroom3) 45)
    (= (moving_time dinning_room1 corridor13) 35)
    (= (moving_time dinning_room1 kitchen1) 25)
    (= (moving_time kitchen1 dinning_room1) 25)
    (= (moving_time library1 corridor13) 40)
    (= (moving_time music_room1 corridor7) 25)
    (= (moving_time sunroom1 corridor8) 40)
    (= (moving_time sunroom10 corridor5) 35)
    (= (moving_time sunroom11 corridor9) 45)
    (= (moving_time sunroom12 corridor10) 25)
    (= (moving_time sunroom13 corridor5) 20)
    (= (moving_time sunroom2 corridor8) 40)
    (= (moving_time sunroom3 corridor9) 45)
    (= (moving_time sunroom4 corridor10) 45)
    (= (moving_time sunroom5 corridor13) 50)
    (= (moving_time sunroom6 corridor1) 50)
    (= (moving_time sunroom7 corridor1) 30)
    (= (moving_time sunroom8 corridor7) 25)
    (= (moving_time sunroom9 corridor7) 35)
    (= (receiving_time) 10)
    (= (suggesting_time) 5)
    (= (suggestion_cost) 500)
    (= (total-cost) 2500)
    (at 3440.0219999999995 (not (comfort_time senior7)))
    (at 3480.0219999999995 (not (comfort_time senior20)))
    (at 3320.0299999999993 (not (hydration_time senior24))))
  (:goal (and
    (soothed senior24)))
  (:metric minimize (+ (total-time) (total-cost)))
)
